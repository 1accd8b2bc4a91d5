transfer examples/pddl/kitchen/blocks_to_kitchen.cp --map BlocksToKitchen --problem examples/pddl/kitchen/sandwich.pddl --plan examples/pddl/kitchen/sandwich.plan --no-timing -o build/golden/kitchen_sandwich/target.plan --problem-output build/golden/kitchen_sandwich/target.pddl
before: rm -rf build/golden/kitchen_sandwich && mkdir -p build/golden/kitchen_sandwich
after: cat build/golden/kitchen_sandwich/target.plan build/golden/kitchen_sandwich/target.pddl
