json export examples/colorblocksworld/colorblocksworld.cp Initial --names
