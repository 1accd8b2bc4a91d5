json export examples/colorblocksworld/colorblocksworld.cp CaseStudy
