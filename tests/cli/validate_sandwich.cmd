validate examples/sandwich_kitchen/sandwich_kitchen.cp --problem MakeSandwich --plan examples/sandwich_kitchen/sandwich.plan
