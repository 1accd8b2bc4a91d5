pddl export tests/pddl/lights.cp --problem LightsProblem -o build/golden/pddl_export_d.pddl --problem-output build/golden/missing/dir/p.pddl
before: mkdir -p build/golden
absent: build/golden/pddl_export_d.pddl
