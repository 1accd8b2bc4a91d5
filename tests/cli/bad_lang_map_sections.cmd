check tests/cli/bad/lang/map_sections.cp
