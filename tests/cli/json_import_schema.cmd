json import tests/cli/data/schgraph.json --name SchGraph
