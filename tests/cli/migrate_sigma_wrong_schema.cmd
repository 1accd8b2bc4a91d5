migrate examples/colorblocks_to_blocks/forget_colors.cp --map ForgetColors Initial --sigma
