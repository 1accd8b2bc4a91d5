plan tests/cli/data/roads.cp --problem ToD --search astar --no-timing
