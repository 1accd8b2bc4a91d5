show --frobnicate examples/colorblocksworld/colorblocksworld.cp Initial
