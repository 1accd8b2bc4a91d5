check tests/cli/bad/lang/import_directory.cp
