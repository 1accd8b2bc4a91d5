json import tests/cli/data/catlab_graphs.cp SchReflexiveGraph tests/cli/data/reflexive_broken.json
