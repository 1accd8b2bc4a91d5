pddl import tests/pddl/shelving-domain.pddl tests/pddl/shelving-p01.pddl
