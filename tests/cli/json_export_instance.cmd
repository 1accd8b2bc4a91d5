json export tests/cli/data/graphs.cp Path2
