(done staining)
