(made smoothie)
