(done repot-fern)
