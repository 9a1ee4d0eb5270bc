(made crate)
