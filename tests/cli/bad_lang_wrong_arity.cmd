check tests/cli/bad/lang/wrong_arity.cp
