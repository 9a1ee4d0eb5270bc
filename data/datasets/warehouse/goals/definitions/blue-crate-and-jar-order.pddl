(and (holding human crate2) (holding human jar1))
