pddl export examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy
