plan tests/cli/data/letting_go.cp --problem Free --no-timing
