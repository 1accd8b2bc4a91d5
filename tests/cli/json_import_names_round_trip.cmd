json import examples/colorblocksworld/colorblocksworld.cp ColorBlocksworld tests/cli/data/initial_names.json --name Initial
