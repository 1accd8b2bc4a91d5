check tests/lang/err_several_at_once.cp
