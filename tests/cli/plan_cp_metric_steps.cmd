plan tests/cli/data/roads.cp --problem ToDInSteps --search astar --no-timing
