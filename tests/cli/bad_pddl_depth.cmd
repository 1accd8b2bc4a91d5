pddl import tests/cli/bad/pddl/depth.pddl
