check examples/colorblocksworld/colorblocksworld.cp --format json
