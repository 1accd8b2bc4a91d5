check -
stdin: tests/cli/bad/lang/stdin.cp
