check tests/cli/bad/lang/encoding.cp
