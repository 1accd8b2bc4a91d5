transfer examples/pddl/blocks/four_to_three.cp --map FourToThree --problem examples/pddl/blocks/p01-4.pddl --plan tests/cli/transfer/batch_pddl/a.plan --plan tests/cli/transfer/batch_pddl/../batch_pddl/a.plan -o build/cli-batch-clash --no-timing
before: rm -rf build/cli-batch-clash
absent: build/cli-batch-clash/a.plan
