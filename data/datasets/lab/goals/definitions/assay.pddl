(done assay)
