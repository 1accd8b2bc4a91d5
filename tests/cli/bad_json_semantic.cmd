json import tests/cli/data/graphs.cp Graph tests/cli/bad/json/semantic.json
