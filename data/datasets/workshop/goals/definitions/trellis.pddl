(made trellis)
