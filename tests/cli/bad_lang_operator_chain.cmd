check tests/cli/bad/lang/operator_chain.cp
