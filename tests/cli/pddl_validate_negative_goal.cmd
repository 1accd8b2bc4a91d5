validate tests/pddl/stacker-domain.pddl tests/pddl/stacker-p01.pddl tests/pddl/stacker-p01-invalid.plan
