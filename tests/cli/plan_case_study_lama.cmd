plan examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --no-timing
