validate examples/hanoi/hanoi.cp --problem ThreeDiscs --plan tests/cli/data/hanoi_larger_on_smaller.plan
