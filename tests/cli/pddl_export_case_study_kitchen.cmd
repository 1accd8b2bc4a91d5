pddl export examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --problem CaseStudy
