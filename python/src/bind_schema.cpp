// catplan.Schema: a planning domain's ontology (objects, homs, attribute types, attributes,
// path equations), immutable and shared by every state on it.

#include "catplan/dot/dot.hpp"
#include "catplan/json/json.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/schema/printer.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

py::list hom_list(const schema::Schema& s) {
    py::list out;
    for (std::uint32_t i = 0; i < s.num_homs(); ++i) {
        const auto& h = s.hom(HomId(i));
        out.append(py::make_tuple(h.name, s.ob(h.dom).name, s.ob(h.codom).name));
    }
    return out;
}

py::list attr_list(const schema::Schema& s) {
    py::list out;
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        const auto& a = s.attr(AttrId(i));
        out.append(py::make_tuple(a.name, s.ob(a.dom).name, s.attr_type(a.codom).name));
    }
    return out;
}

py::list equation_list(const schema::Schema& s) {
    py::list out;
    for (const auto& e : s.equations()) {
        out.append(py::make_tuple(e.name, s.path_to_string(e.lhs), s.path_to_string(e.rhs)));
    }
    return out;
}

} // namespace

namespace {

PySchema schema_from_json(const std::string& text, const std::string& name,
                          const std::string& filename) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer(filename, text);
    schema::SchemaPtr s;
    {
        py::gil_scoped_release release;
        s = json::read_schema(name, file, sources, sink);
    }
    if (s == nullptr || sink.has_errors()) {
        throw error_from(sources, sink);
    }
    return PySchema{s};
}

} // namespace

void bind_schema(py::module_& m) {
    py::class_<PySchema>(m, "Schema", R"doc(
A schema: the ontology of a planning domain, a finitely presented category with attributes
(Catlab's ``@present``). Immutable; states, rules and maps share it.

Objects, homs, attribute types and attributes are listed in declaration order. Two Schema
objects are equal when they are the same schema (as loaded), not merely alike.)doc")
        .def_property_readonly("name", [](const PySchema& s) { return s.ptr->name(); })
        .def_property_readonly(
            "obs",
            [](const PySchema& s) {
                std::vector<std::string> out;
                for (std::uint32_t i = 0; i < s.ptr->num_obs(); ++i) {
                    out.push_back(s.ptr->ob(ObId(i)).name);
                }
                return out;
            },
            "The object names.")
        .def_property_readonly(
            "homs", [](const PySchema& s) { return hom_list(*s.ptr); },
            "The homs as (name, dom, codom) tuples.")
        .def_property_readonly(
            "attr_types",
            [](const PySchema& s) {
                py::list out;
                for (std::uint32_t i = 0; i < s.ptr->num_attr_types(); ++i) {
                    const auto& t = s.ptr->attr_type(AttrTypeId(i));
                    out.append(py::make_tuple(t.name, std::string(schema::to_string(t.kind))));
                }
                return out;
            },
            "The attribute types as (name, kind) tuples; kind is 'Bool', 'Int', 'Float', "
            "'String' or 'Unknown'.")
        .def_property_readonly(
            "attrs", [](const PySchema& s) { return attr_list(*s.ptr); },
            "The attributes as (name, dom, attribute type) tuples.")
        .def_property_readonly(
            "equations", [](const PySchema& s) { return equation_list(*s.ptr); },
            "The path equations as (name, lhs, rhs) tuples, paths written 'f ⋅ g'.")
        .def(
            "kind",
            [](const PySchema& s, const std::string& name) {
                auto g = s.ptr->find(name);
                if (!g) {
                    throw py::key_error("schema " + s.ptr->name() + " declares no '" + name + "'");
                }
                static const char* const kinds[] = {"Ob", "Hom", "AttrType", "Attr"};
                return std::string(kinds[static_cast<int>(g->kind)]);
            },
            py::arg("name"),
            "What a name is: 'Ob', 'Hom', 'AttrType' or 'Attr' (KeyError if none).")
        .def(
            "__contains__",
            [](const PySchema& s, const std::string& name) {
                return s.ptr->find(name).has_value();
            },
            py::arg("name"))
        .def(
            "describe", [](const PySchema& s) { return schema::describe(*s.ptr); },
            "The schema as lists, as `catplan show` prints it.")
        .def(
            "to_text", [](const PySchema& s) { return lang::print_schema(*s.ptr); },
            "The schema in @present form, loadable again.")
        .def(
            "to_json",
            [](const PySchema& s, bool pretty) { return json::write_schema(*s.ptr, pretty); },
            py::arg("pretty") = false, "Catlab's schema JSON.")
        .def_static("from_json", &schema_from_json, py::arg("text"), py::arg("name") = "Schema",
                    py::arg("filename") = "<json>",
                    "Reads Catlab's schema JSON; raises CatplanError with located diagnostics.")
        .def(
            "to_dot",
            [](const PySchema& s, bool left_to_right) {
                dot::DotOptions o;
                o.left_to_right = left_to_right;
                return dot::schema_to_dot(*s.ptr, o);
            },
            py::arg("left_to_right") = false, "A Graphviz DOT picture of the schema.")
        .def("__eq__", [](const PySchema& a, const PySchema& b) { return a.ptr == b.ptr; })
        .def("__hash__", [](const PySchema& s) { return std::hash<const void*>()(s.ptr.get()); })
        .def("__str__", [](const PySchema& s) { return lang::print_schema(*s.ptr); })
        .def("__repr__", [](const PySchema& s) {
            const auto& x = *s.ptr;
            return "<Schema " + x.name() + ": " + std::to_string(x.num_obs()) + " objects, " +
                   std::to_string(x.num_homs()) + " homs, " + std::to_string(x.num_attr_types()) +
                   " attribute types, " + std::to_string(x.num_attrs()) + " attributes>";
        });
}

} // namespace catplan::python
