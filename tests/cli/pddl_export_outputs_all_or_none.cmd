pddl export tests/pddl/lights.cp --problem LightsProblem -o build/golden/missing/dir/d.pddl --problem-output build/golden/pddl_export_p.pddl
before: mkdir -p build/golden
absent: build/golden/pddl_export_p.pddl
