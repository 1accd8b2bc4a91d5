validate tests/cli/bad/pddl/rooms-domain.pddl tests/cli/bad/pddl/rooms-p01.pddl tests/cli/bad/ipc/not_applicable.plan
