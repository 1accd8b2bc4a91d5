check tests/pddl/unsupported.cp
