json export tests/lang/err_several_at_once.cp X -o tests/cli/data/out.json
absent: tests/cli/data/out.json
