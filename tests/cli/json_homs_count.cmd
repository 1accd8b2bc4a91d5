homs examples/colorblocksworld/colorblocksworld.cp Goal Initial --count --format json
