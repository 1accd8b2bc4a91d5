check tests/cli/data/no_such_file.cp
