plan examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --max-time nan
