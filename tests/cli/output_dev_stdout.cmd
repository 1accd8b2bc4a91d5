json export tests/cli/data/graphs.cp Cycle3 -o /dev/stdout
