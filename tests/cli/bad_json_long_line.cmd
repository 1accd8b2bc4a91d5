json import tests/cli/data/graphs.cp Graph tests/cli/data/long_line.json
