validate examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --plan tests/cli/data/bad_step.plan
