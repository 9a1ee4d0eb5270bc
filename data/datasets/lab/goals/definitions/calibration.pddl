(done calibration)
