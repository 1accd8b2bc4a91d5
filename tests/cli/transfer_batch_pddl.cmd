transfer examples/pddl/blocks/four_to_three.cp --map FourToThree --problem examples/pddl/blocks/p01-4.pddl --plan tests/cli/transfer/batch_pddl --no-timing -o build/cli-batch-pddl
before: rm -rf build/cli-batch-pddl
after: ls build/cli-batch-pddl && cat build/cli-batch-pddl/*.plan
