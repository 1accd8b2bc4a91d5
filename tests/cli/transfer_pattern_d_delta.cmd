transfer examples/colorblocks_to_blocks/forget_colors.cp --map ForgetColors --problem CaseStudy --plan examples/colorblocksworld/paper.plan --no-timing
