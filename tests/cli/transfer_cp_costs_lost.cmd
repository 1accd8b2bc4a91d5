transfer tests/cli/data/roads_to_transit.cp --map BusesToRoads --problem ToD --plan tests/cli/data/roads_cheapest.plan --no-timing
