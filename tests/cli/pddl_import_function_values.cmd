pddl import tests/pddl/roads-domain.pddl tests/pddl/roads-p01.pddl
