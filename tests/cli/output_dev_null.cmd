json export tests/cli/data/graphs.cp Cycle3 -o /dev/null
after: stat -c '%F %n' /dev/null
