homs tests/cli/data/graphs.cp Graph Cycle3
