transfer examples/colorblocks_to_kitchen/swapped_map.cp --map ColorToKitchen --problem CaseStudy --plan examples/colorblocksworld/paper.plan --goal Sandwich --format json --no-timing
