dot examples/colorblocksworld/colorblocksworld.cp unstack
