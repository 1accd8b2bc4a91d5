validate tests/cli/data/int_overflow.cp --problem Overflow --plan tests/cli/data/int_overflow.plan
