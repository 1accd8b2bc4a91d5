transfer examples/colorblocks_to_kitchen/bad_gripper_map.cp --map GripperToBlock --problem CaseStudy --plan examples/colorblocksworld/paper.plan
