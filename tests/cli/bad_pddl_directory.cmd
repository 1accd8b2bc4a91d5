plan tests/cli/bad/pddl tests/cli/bad/pddl/rooms-p01.pddl
