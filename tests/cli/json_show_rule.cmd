show tests/cli/data/int_overflow.cp inc --format json
