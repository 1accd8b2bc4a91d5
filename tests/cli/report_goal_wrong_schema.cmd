report examples/colorblocks_to_kitchen/swapped_map.cp --map SwappedToKitchen --problem CaseStudy --plan examples/colorblocksworld/paper.plan --goal Initial -o build/report_wrong_goal.html
absent: build/report_wrong_goal.html
