homs --help
