check tests/cli/bad/lang/identifier.cp
