(done sow-seeds)
