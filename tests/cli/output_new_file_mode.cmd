json export tests/cli/data/graphs.cp Cycle3 -o build/golden/output_new_file_mode/cycle3.json
before: rm -rf build/golden/output_new_file_mode && mkdir -p build/golden/output_new_file_mode
after: stat -c '%a %F %n' build/golden/output_new_file_mode/*
