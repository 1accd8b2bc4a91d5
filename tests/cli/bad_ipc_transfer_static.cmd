transfer examples/pddl/blocks/three_to_four.cp --map ThreeToFour --problem examples/pddl/blocks/p01-3.pddl --plan tests/cli/bad/ipc/blocks3_static.plan -o build/bad_ipc_transfer.plan --problem-output build/bad_ipc_transfer.pddl
absent: build/bad_ipc_transfer.plan
absent: build/bad_ipc_transfer.pddl
