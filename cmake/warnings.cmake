# Warnings for our own code only (added per target by catplan_add_layer).
set(CATPLAN_WARNINGS
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wmissing-declarations
    -Wzero-as-null-pointer-constant)
if(DEFINED ENV{CI})
    # CI treats a warning as a failure so none creeps in unnoticed.
    list(APPEND CATPLAN_WARNINGS -Werror)
endif()
