plan examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --search gbfs --no-timing
