transfer examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --problem CaseStudy --plan examples/colorblocksworld/paper.plan --replan --search bfs --max-nodes 2 --no-timing
