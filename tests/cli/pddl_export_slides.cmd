pddl export examples/colorblocksworld/slides.cp --problem SlidesCaseStudy
