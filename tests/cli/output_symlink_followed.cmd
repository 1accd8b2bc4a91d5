json export tests/cli/data/graphs.cp Cycle3 -o build/golden/output_symlink/link.json
before: rm -rf build/golden/output_symlink && mkdir -p build/golden/output_symlink && echo old > build/golden/output_symlink/real.json && chmod 0600 build/golden/output_symlink/real.json && ln -s real.json build/golden/output_symlink/link.json
after: stat -c '%a %F %n' build/golden/output_symlink/*
after: readlink build/golden/output_symlink/link.json
after: head -c 40 build/golden/output_symlink/real.json; echo
