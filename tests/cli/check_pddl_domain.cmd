check examples/pddl/blocks/blocks3.pddl examples/pddl/blocks/blocks4.pddl
