plan tests/pddl/shuttle-domain.pddl tests/pddl/shuttle-p01.pddl --no-timing -o build/golden/pddl_plan_costs_output/shuttle.plan
before: rm -rf build/golden/pddl_plan_costs_output && mkdir -p build/golden/pddl_plan_costs_output
after: cat build/golden/pddl_plan_costs_output/shuttle.plan
