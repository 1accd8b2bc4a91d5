plan tests/pddl/blocksworld-domain.pddl tests/pddl/blocksworld-p01.pddl --search astar --heuristic hff --no-timing
