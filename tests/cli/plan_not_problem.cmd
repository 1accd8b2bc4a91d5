plan examples/colorblocksworld/colorblocksworld.cp --problem Initial
