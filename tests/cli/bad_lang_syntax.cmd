check tests/cli/bad/lang/syntax.cp
