show examples/colorblocksworld/colorblocksworld.cp Goal
