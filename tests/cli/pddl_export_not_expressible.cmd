pddl export examples/colorblocksworld/colorblocksworld.cp --domain Blocksworld
