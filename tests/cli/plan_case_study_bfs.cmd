plan examples/colorblocksworld/colorblocksworld.cp --domain Blocksworld --problem CaseStudy --no-timing
