pddl import tests/cli/bad/pddl/bom_cr.pddl
