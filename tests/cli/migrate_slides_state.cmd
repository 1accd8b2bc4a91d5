migrate examples/colorblocks_to_kitchen/slides_map.cp --map ColorToKitchen state
