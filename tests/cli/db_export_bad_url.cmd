db export examples/colorblocksworld/colorblocksworld.cp Initial --db mysql://localhost/x
