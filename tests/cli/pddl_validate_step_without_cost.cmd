validate tests/pddl/roads-domain.pddl tests/pddl/roads-p01.pddl tests/pddl/roads-p01-through-e.plan
