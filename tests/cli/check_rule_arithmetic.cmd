check tests/lang/err_rule_arithmetic.cp
