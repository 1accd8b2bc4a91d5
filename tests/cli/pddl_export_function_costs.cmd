pddl export tests/cli/data/roads.cp --problem ToD
