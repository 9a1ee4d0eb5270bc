(made crumble)
