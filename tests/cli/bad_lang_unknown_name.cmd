check tests/cli/bad/lang/unknown_name.cp
