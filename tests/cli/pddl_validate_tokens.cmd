validate tests/pddl/shuttle-domain.pddl tests/pddl/shuttle-p01.pddl tests/pddl/shuttle-p01.plan
