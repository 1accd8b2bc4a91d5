check examples/pddl/blocks/p01-3.pddl
