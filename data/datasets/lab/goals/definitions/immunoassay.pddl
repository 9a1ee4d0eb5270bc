(done immunoassay)
