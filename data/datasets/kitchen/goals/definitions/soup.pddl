(made soup)
