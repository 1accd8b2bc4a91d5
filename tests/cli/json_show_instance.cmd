show examples/colorblocksworld/colorblocksworld.cp Initial --format json
