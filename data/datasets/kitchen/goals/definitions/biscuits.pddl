(made biscuits)
