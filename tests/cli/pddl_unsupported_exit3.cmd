plan tests/pddl/unsupported-domain.pddl tests/pddl/lift-p01.pddl
