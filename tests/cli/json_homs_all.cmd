homs tests/cli/data/graphs.cp Path2 Cycle3 --all --format json
