plan tests/pddl/roads-domain.pddl tests/pddl/roads-p01.pddl --search bfs --format json --no-timing
