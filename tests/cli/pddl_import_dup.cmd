pddl import tests/pddl/dup-domain.pddl tests/pddl/dup-p01.pddl
