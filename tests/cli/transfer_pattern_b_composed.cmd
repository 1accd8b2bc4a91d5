transfer examples/kitchen_to_warehouse/kitchen_to_warehouse.cp --map KitchenToWarehouse --problem MakeSandwich --plan examples/sandwich_kitchen/sandwich.plan --rename-by-type --no-timing
