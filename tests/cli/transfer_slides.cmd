transfer examples/colorblocks_to_kitchen/slides_map.cp --map ColorToKitchen --problem SlidesCaseStudy --plan examples/colorblocksworld/paper.plan --rename-by-type --no-timing
