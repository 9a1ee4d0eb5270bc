(made mousse)
