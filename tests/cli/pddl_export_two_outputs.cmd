pddl export tests/pddl/lights.cp --problem LightsProblem -o build/golden/pddl_two/d.pddl --problem-output build/golden/pddl_two/p.pddl
before: rm -rf build/golden/pddl_two && mkdir -p build/golden/pddl_two
after: stat -c '%a %F %n' build/golden/pddl_two/*
after: head -n 1 build/golden/pddl_two/d.pddl build/golden/pddl_two/p.pddl
