plan tests/pddl/adl-rooms-domain.pddl tests/pddl/adl-rooms-p01.pddl --no-timing
