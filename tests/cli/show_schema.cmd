show examples/kitchenworld/kitchenworld.cp KitchenWorld
