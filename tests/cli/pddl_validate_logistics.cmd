validate tests/pddl/logistics-domain.pddl tests/pddl/logistics-p01.pddl tests/pddl/logistics-p01.plan
