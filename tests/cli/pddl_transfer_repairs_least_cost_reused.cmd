transfer tests/pddl/roads_to_transit.cp --map ToCharters --problem tests/pddl/roads-chain.pddl --plan tests/pddl/roads-chain.plan --no-timing
