transfer tests/pddl/roads_to_transit.cp --map ToTransit --problem tests/pddl/roads-p01.pddl --plan tests/pddl/roads-p01.plan --no-timing -o build/cli-transit.plan --problem-output build/cli-transit.pddl
after: cat build/cli-transit.plan build/cli-transit.pddl
