transfer examples/pddl/kitchen/blocks_to_kitchen.cp --map BlocksToKitchen --problem examples/pddl/kitchen/sandwich-paint.pddl --plan examples/pddl/kitchen/sandwich-paint.plan --no-timing
