transfer examples/kitchen_to_colorblocks/kitchen_to_color.cp --map KitchenToColor --problem MakeSandwich --plan examples/sandwich_kitchen/sandwich.plan --no-timing
