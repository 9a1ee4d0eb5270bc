(made pilaf)
