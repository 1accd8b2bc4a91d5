check tests/cli/bad/lang/lexical.cp
