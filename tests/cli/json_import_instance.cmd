json import tests/cli/data/graphs.cp Graph tests/cli/data/path3.json
