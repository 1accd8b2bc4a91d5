transfer examples/pddl/blocks/four_to_three.cp --map FourToThree --problem examples/pddl/blocks/p01-4.pddl --plan examples/pddl/blocks/p01-4.plan --no-timing
