check tests/cli/bad/lang/depth.cp
