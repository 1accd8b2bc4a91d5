homs tests/cli/data/graphs.cp Cycle3 Bowtie --count
