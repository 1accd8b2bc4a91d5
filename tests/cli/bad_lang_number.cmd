check tests/cli/bad/lang/number.cp
