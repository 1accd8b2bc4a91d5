homs tests/cli/data/graphs.cp Cycle3 Cycle3 --iso --count
