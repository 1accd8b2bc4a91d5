check tests/cli/bad/lang/bom_cr.cp
