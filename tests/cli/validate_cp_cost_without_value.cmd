validate tests/cli/data/roads.cp --problem ToD --plan tests/cli/data/roads_through_e.plan
