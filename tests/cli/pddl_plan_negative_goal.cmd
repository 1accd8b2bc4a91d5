plan tests/pddl/stacker-domain.pddl tests/pddl/stacker-p01.pddl --no-timing
