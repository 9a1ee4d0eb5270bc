(done digestion)
