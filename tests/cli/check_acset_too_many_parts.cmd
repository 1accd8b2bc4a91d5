check tests/lang/err_acset_too_many_parts.cp
