homs examples/colorblocksworld/colorblocksworld.cp Goal Initial --monic --format json
