transfer examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --problem CaseStudy --plan examples/colorblocksworld/paper.plan --replan --search gbfs --max-nodes 1000 --no-timing
