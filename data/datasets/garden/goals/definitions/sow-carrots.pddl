(done sow-carrots)
