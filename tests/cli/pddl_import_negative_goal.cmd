pddl import tests/pddl/stacker-domain.pddl tests/pddl/stacker-p01.pddl
