pddl export tests/pddl/not_expressible.cp --domain PaintDomain
