transfer tests/cli/data/roads_to_transit.cp --map TransitToRoads --problem ToD --plan tests/cli/data/roads_through_e.plan --format json --no-timing
