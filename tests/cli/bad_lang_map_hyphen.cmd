check tests/cli/bad/lang/map_hyphen.cp
