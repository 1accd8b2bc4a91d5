validate examples/hanoi/hanoi.cp --problem ThreeDiscs --plan examples/hanoi/hanoi.plan
