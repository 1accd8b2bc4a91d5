migrate tests/lang/err_map_wrong_ends.cp --map Bad Anything
