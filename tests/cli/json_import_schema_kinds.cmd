json import tests/cli/data/schema_kinds.json --name Weighted
