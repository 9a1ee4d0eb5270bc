(made gratin)
