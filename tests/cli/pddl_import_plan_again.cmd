plan build/golden/pddl_import_plan_again/blocks4.cp --problem tower3 --no-timing -o build/golden/pddl_import_plan_again/tower3.plan
before: rm -rf build/golden/pddl_import_plan_again && mkdir -p build/golden/pddl_import_plan_again && $CATPLAN pddl import examples/pddl/blocks/blocks4.pddl examples/pddl/blocks/p01-4.pddl -o build/golden/pddl_import_plan_again/blocks4.cp
after: $CATPLAN validate build/golden/pddl_import_plan_again/blocks4.cp --problem tower3 --plan build/golden/pddl_import_plan_again/tower3.plan 2>&1; echo "exit $?"
