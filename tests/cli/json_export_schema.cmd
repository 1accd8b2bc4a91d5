json export examples/colorblocksworld/colorblocksworld.cp ColorBlocksworld --pretty
