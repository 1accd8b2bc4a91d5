transfer tests/cli/data/roads_to_transit.cp --map TransitToRoads --problem ToD --plan tests/cli/data/roads_cheapest.plan --replan --search astar --no-timing
