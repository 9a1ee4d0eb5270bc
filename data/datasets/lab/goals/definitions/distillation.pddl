(done distillation)
