(made bookcase)
