json export tests/cli/data/graphs.cp Cycle3 -o build/golden/output_replaced/cycle3.json
before: rm -rf build/golden/output_replaced && mkdir -p build/golden/output_replaced && echo old > build/golden/output_replaced/cycle3.json && chmod 0640 build/golden/output_replaced/cycle3.json
after: stat -c '%a %F %n' build/golden/output_replaced/*
after: head -c 40 build/golden/output_replaced/cycle3.json; echo
