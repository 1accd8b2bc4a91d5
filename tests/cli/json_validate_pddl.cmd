validate examples/pddl/blocks/blocks3.pddl examples/pddl/blocks/p01-3.pddl examples/pddl/blocks/p01-3.plan --format json
