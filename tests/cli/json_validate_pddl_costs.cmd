validate tests/pddl/lift-domain.pddl tests/pddl/lift-p01.pddl tests/pddl/lift-p01.plan --format json
