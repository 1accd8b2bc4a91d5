validate examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --plan tests/cli/no-such.plan --format json
