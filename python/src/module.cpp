// The extension module catplan._catplan; the package catplan re-exports it (python/catplan).

#include "common.hpp"

PYBIND11_MODULE(_catplan, m) {
    using namespace catplan::python;
    m.doc() = "catplan's library: categorical task planning and plan transfer.";
    register_errors(m);
    bind_values(m);
    bind_schema(m);
    bind_state(m);
    bind_module(m);
    bind_hom(m);
    bind_plan(m);
    bind_migrate(m);
    bind_io(m);
    bind_transfer(m);
    bind_pddl_transfer(m);
}
