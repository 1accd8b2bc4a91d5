validate examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --plan -
stdin: examples/colorblocksworld/paper.plan
