show tests/cli/data/letting_go.cp Free --format json
