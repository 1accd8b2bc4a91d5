show tests/pddl/roads_to_transit.cp ToCharters --format json
