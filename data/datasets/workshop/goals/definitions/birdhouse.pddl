(made birdhouse)
