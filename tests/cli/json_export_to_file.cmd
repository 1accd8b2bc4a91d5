json export tests/cli/data/graphs.cp Cycle3 -o build/cli_cycle3.json
