check tests/lang/catlab_pasted.cp
