dot tests/cli/data/graphs.cp Cycle3 --lr
