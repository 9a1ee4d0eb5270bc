(done feed-roses)
