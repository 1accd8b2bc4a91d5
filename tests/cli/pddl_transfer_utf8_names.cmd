transfer examples/pddl/blocks/three_to_four.cp --map ThreeToFour --problem tests/pddl/blocks3-utf8-names.pddl --plan tests/pddl/blocks3-utf8-names.plan --no-timing
