plan tests/pddl/lift-domain.pddl tests/pddl/lift-p01.pddl --no-timing
