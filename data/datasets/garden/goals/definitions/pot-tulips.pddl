(done pot-tulips)
