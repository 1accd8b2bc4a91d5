pddl import examples/pddl/blocks/blocks3.pddl examples/pddl/blocks/p01-3.pddl --format json
