(done pot-herbs)
