(made applesauce)
