transfer examples/hanoi_to_blocks/hanoi_to_blocks.cp --map HanoiToBlocks --problem ThreeDiscs --plan examples/hanoi/hanoi.plan --format json --no-timing
