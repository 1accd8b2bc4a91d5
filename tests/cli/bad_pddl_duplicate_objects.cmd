pddl import tests/cli/bad/pddl/rooms-domain.pddl tests/cli/bad/pddl/duplicate-objects.pddl
