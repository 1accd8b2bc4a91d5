transfer tests/pddl/roads_to_transit.cp --map ToCharters --problem tests/pddl/roads-p01.pddl --plan tests/pddl/roads-p01.plan --no-timing
