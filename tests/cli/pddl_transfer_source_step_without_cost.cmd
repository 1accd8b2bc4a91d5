transfer tests/pddl/roads_to_transit.cp --map ToTransit --problem tests/pddl/roads-p01.pddl --plan tests/pddl/roads-p01-through-e.plan --no-timing
