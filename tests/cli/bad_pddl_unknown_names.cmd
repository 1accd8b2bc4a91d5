pddl import tests/cli/bad/pddl/unknown_names.pddl
