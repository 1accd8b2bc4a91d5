validate examples/colorblocksworld/colorblocksworld.cp --domain Blocksworld --problem CaseStudy --plan examples/colorblocksworld/paper.plan --format json
