transfer examples/pddl/blocks/three_to_four.cp --map ThreeToFour --problem examples/pddl/blocks/p02-3.pddl --plan examples/pddl/blocks/p02-3.plan --no-timing --format json
