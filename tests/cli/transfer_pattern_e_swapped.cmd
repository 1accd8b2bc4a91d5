transfer examples/colorblocks_to_kitchen/swapped_map.cp --map SwappedToKitchen --problem CaseStudy --plan examples/colorblocksworld/paper.plan --goal Sandwich --rename-by-type --no-timing
