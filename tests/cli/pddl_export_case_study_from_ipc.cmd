pddl export examples/colorblocksworld/colorblocksworld.cp --problem CaseStudy --from-ipc tests/pddl/case_study_export.ipc
