plan examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --max-memory -5
