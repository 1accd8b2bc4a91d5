show examples/colorblocks_to_kitchen/appendix_map.cp ColorToKitchen --format json
