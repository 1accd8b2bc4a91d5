// catplan.Map (an ontology map F : D' -> D) and data migration along it: migrate (Δ_F),
// sigma (Σ_F), migrate_domain (the target domain's generated actions), compose.

#include "catplan/dot/dot.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/describe.hpp"
#include "catplan/migrate/migration.hpp"
#include "catplan/migrate/sigma.hpp"
#include "catplan/transfer/transfer.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

/// ValueError unless x is on s (or a schema of the same shape).
void require_on(const acset::ACSet& x, const schema::SchemaPtr& s) {
    if (x.schema_ptr() != s) {
        require_same_schema(x, acset::ACSet(s));
    }
}

PyState migrate_state(const PyMap& f, PyState& state) {
    auto x = state.share();
    require_on(*x, f.ptr->source());
    acset::ACSet y(f.ptr->target());
    {
        py::gil_scoped_release release;
        y = migrate::migrate(*f.ptr, *x);
    }
    return PyState::owned(std::move(y), state.name());
}

PyState sigma(const PyMap& f, PyState& state, std::size_t max_parts) {
    auto y = state.share();
    require_on(*y, f.ptr->target());
    if (!f.ptr->is_delta()) {
        throw error_from("Σ is defined along a delta map; " + f.name + " is conjunctive");
    }
    std::optional<Result<acset::ACSet>> x;
    {
        py::gil_scoped_release release;
        x.emplace(migrate::sigma(*f.ptr, *y, max_parts));
    }
    return PyState::owned(value_or_raise(std::move(*x)), state.name());
}

PyDomain migrate_domain(const PyMap& f, const PyDomain& d, const std::string& name,
                        bool allow_failures) {
    if (d.ptr->schema != f.ptr->source()) {
        throw py::value_error("domain " + d.ptr->name + " is on " + d.ptr->schema->name() +
                              ", but map " + f.name + " migrates " + f.ptr->source()->name());
    }
    transfer::MigratedDomain md;
    {
        py::gil_scoped_release release;
        md = transfer::migrate_domain(*f.ptr, *d.ptr, name);
    }
    if (!md.failures.empty() && !allow_failures) {
        std::string why;
        for (const auto& [rule, reason] : md.failures) {
            why += (why.empty() ? "" : "; ") + std::string("rule ") + rule +
                   " cannot be migrated: " + reason;
        }
        throw error_from(why);
    }
    return PyDomain{md.domain};
}

PyMap compose(const PyMap& first, const PyMap& second, const std::string& name) {
    return PyMap{std::make_shared<const migrate::SchemaMap>(
                     value_or_raise(migrate::compose(*first.ptr, *second.ptr))),
                 name.empty() ? second.name + "∘" + first.name : name};
}

} // namespace

void bind_migrate(py::module_& m) {
    py::class_<PyMap>(m, "Map", R"doc(
An ontology map F : D' -> D from a target schema D' to queries over a source schema D (the
paper's F : Kitchenworld -> ColorBlocksworld). Data flows the other way: migrate carries states
on D to states on D'. A delta map sends objects to objects; a conjunctive one may send an
object to a query (the blocks of one colour).)doc")
        .def_readonly("name", &PyMap::name)
        .def_property_readonly(
            "target", [](const PyMap& f) { return PySchema{f.ptr->target()}; },
            "D', the schema of the migrated states.")
        .def_property_readonly(
            "source", [](const PyMap& f) { return PySchema{f.ptr->source()}; },
            "D, the schema of the states migrated.")
        .def_property_readonly("is_delta", [](const PyMap& f) { return f.ptr->is_delta(); })
        .def_property_readonly(
            "kind", [](const PyMap& f) { return f.ptr->is_delta() ? "delta" : "conjunctive"; })
        .def(
            "describe",
            [](const PyMap& f) {
                py::list out;
                for (const auto& line : migrate::describe_map(*f.ptr)) {
                    out.append(py::make_tuple(line.name, line.image));
                }
                return out;
            },
            "Each target generator with its image in words, as (name, image) tuples.")
        .def(
            "to_dot", [](const PyMap& f) { return dot::map_to_dot(*f.ptr, f.name); },
            "A Graphviz DOT picture: both schemas side by side, the images as dashed edges.")
        .def("migrate", &migrate_state, py::arg("state"), "Δ_F(state); see catplan.migrate.")
        .def("sigma", &sigma, py::arg("state"), py::arg("max_parts") = 1000000,
             "Σ_F(state); see catplan.sigma.")
        .def("__str__",
             [](const PyMap& f) { return migrate::map_text(migrate::describe_map(*f.ptr)); })
        .def("__repr__", [](const PyMap& f) {
            return "<Map " + f.name + " : " + f.ptr->target()->name() + " -> " +
                   f.ptr->source()->name() + " (" + (f.ptr->is_delta() ? "delta" : "conjunctive") +
                   ")>";
        });

    m.def("migrate", &migrate_state, py::arg("map"), py::arg("state"),
          "Δ_F(state): a state on the map's source schema carried to its target schema (the "
          "paper's Table 1). Part names are carried along.");
    m.def("sigma", &sigma, py::arg("map"), py::arg("state"), py::arg("max_parts") = 1000000,
          "Σ_F(state), the left adjoint of Δ_F, along a delta map: a state on the target "
          "schema pushed to the source. Raises CatplanError when the map is not delta, two "
          "constants are identified, or the result would exceed max_parts.");
    m.def("migrate_domain", &migrate_domain, py::arg("map"), py::arg("domain"),
          py::arg("name") = "", py::arg("allow_failures") = false,
          "Δ_F of every rule of a domain: the target domain's generated actions. Raises "
          "CatplanError naming each rule that cannot be migrated, unless allow_failures, "
          "which leaves those rules out.");
    m.def("compose", &compose, py::arg("first"), py::arg("second"), py::arg("name") = "",
          "The map whose migration is second's after first's (first : D' -> D, second : D'' -> "
          "D'); one of them must be delta.");
}

} // namespace catplan::python
