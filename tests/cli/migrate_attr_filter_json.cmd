migrate tests/cli/data/attr_filter.cp --map M T --format json
