check tests/cli/bad
