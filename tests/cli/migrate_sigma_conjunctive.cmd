migrate examples/colorblocks_to_kitchen/swapped_map.cp --map ColorToKitchen Sandwich --sigma
