json import tests/cli/data/catlab_graphs.cp SchWeightedGraph tests/cli/data/catlab_2022.json
