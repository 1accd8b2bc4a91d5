transfer tests/pddl/roads_to_transit.cp --map ToFares --problem tests/pddl/roads-p01.pddl --plan tests/pddl/roads-p01.plan --no-timing
