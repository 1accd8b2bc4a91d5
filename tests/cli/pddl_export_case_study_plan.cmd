pddl export examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --plan examples/colorblocksworld/paper.plan
