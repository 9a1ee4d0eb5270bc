(made frittata)
