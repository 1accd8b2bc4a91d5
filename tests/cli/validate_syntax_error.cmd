validate examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --plan tests/cli/data/syntax.plan
