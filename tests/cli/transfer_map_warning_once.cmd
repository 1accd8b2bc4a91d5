transfer tests/cli/transfer/identity_map.cp --map Itself --problem CaseStudy --plan examples/colorblocksworld/paper.plan --no-timing
