plan tests/pddl/shelving-domain.pddl tests/pddl/shelving-p01.pddl --no-timing
