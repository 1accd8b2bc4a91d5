plan tests/pddl/shuttle-domain.pddl tests/pddl/shuttle-p01.pddl --search astar --no-timing
