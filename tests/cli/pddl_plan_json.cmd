plan tests/pddl/blocksworld-domain.pddl tests/pddl/blocksworld-p01.pddl --search astar --format json --no-timing
