(and (holding human crate1) (holding human jar1))
