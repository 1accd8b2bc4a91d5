json import tests/cli/data/graphs.cp Graph -
stdin: tests/cli/data/path3.json
