// catplan.State: an attributed C-set (a planning state) with parts, homs and attributes as
// Python values, built from and turned into plain Python data.

#include "catplan/acset/printer.hpp"
#include "catplan/dot/dot.hpp"
#include "catplan/json/json.hpp"
#include "catplan/lang/module.hpp"

#include <algorithm>
#include <unordered_map>

#include "common.hpp"

namespace catplan::python {

PyState PyState::empty(const schema::SchemaPtr& s, std::string name) {
    return owned(acset::ACSet(s), std::move(name));
}

PyState PyState::owned(acset::ACSet x, std::string name) {
    PyState st(std::make_shared<acset::ACSet>(std::move(x)), std::move(name));
    st.owner_ = true;
    return st;
}

acset::ACSet& PyState::mut() {
    if (!owner_) {
        ptr_ = std::make_shared<acset::ACSet>(*ptr_);
        owner_ = true;
    }
    // Made by make_shared<ACSet> above or in owned(): the object itself is not const.
    return const_cast<acset::ACSet&>(*ptr_);
}

namespace {

using acset::ACSet;

/// Parts of one object by name, for resolving many references at once.
using NameIndex = std::unordered_map<std::string, Part>;

NameIndex name_index(const ACSet& x, ObId ob) {
    NameIndex out;
    for (Part p = 0; p < x.num_parts(ob); ++p) {
        auto n = x.part_name(ob, p);
        if (!n.empty()) {
            out.emplace(std::string(n), p); // the first part of a name wins, as find_part
        }
    }
    return out;
}

/// A hom target given as an index or a name, resolved through an index of names when given.
Part target_part(const ACSet& x, ObId codom, const py::handle& v, const NameIndex* names) {
    if (names != nullptr && py::isinstance<py::str>(v)) {
        auto it = names->find(v.cast<std::string>());
        if (it == names->end()) {
            throw py::key_error("no part of " + x.schema().ob(codom).name + " is named '" +
                                v.cast<std::string>() + "'");
        }
        return it->second;
    }
    return part_arg(x, codom, v);
}

/// Sets one cell of part p of ob: a hom (to a part index or name, None unsets) or an attribute.
void set_cell(ACSet& x, ObId ob, Part p, const std::string& key, const py::handle& v,
              const NameIndex* names_of_codom = nullptr) {
    const auto& s = x.schema();
    auto g = hom_or_attr_named(s, key);
    if (g.kind == schema::GeneratorKind::Hom) {
        HomId f(g.index);
        if (s.hom(f).dom != ob) {
            throw py::key_error("hom " + key + " goes out of " + s.ob(s.hom(f).dom).name +
                                ", not " + s.ob(ob).name);
        }
        x.set_subpart(f, p,
                      v.is_none() ? kNoPart : target_part(x, s.hom(f).codom, v, names_of_codom));
        return;
    }
    AttrId a(g.index);
    if (s.attr(a).dom != ob) {
        throw py::key_error("attribute " + key + " belongs to " + s.ob(s.attr(a).dom).name +
                            ", not " + s.ob(ob).name);
    }
    x.set_subpart(a, p, from_python(x, s.attr(a).codom, v));
}

py::object name_or_none(std::string_view n) {
    return n.empty() ? py::object(py::none()) : py::object(py::str(std::string(n)));
}

py::dict row_of(const ACSet& x, ObId ob, Part p) {
    const auto& s = x.schema();
    py::dict row;
    row["_name"] = name_or_none(x.part_name(ob, p));
    for (HomId f : s.homs_from(ob)) {
        Part q = x.subpart(f, p);
        row[py::str(s.hom(f).name)] = q == kNoPart ? py::object(py::none()) : py::int_(q);
    }
    for (AttrId a : s.attrs_from(ob)) {
        row[py::str(s.attr(a).name)] = to_python(x, s.attr(a).codom, x.subpart(a, p));
    }
    return row;
}

py::dict to_dict(const ACSet& x) {
    const auto& s = x.schema();
    py::dict out;
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        ObId ob(i);
        py::list rows;
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            rows.append(row_of(x, ob, p));
        }
        out[py::str(s.ob(ob).name)] = rows;
    }
    for (std::uint32_t i = 0; i < s.num_attr_types(); ++i) {
        AttrTypeId t(i);
        if (x.num_vars(t) == 0) {
            continue;
        }
        py::list vars;
        for (std::uint32_t j = 0; j < x.num_vars(t); ++j) {
            py::dict v;
            v["_name"] = name_or_none(x.var_name(t, j));
            vars.append(v);
        }
        out[py::str(s.attr_type(t).name)] = vars;
    }
    return out;
}

std::string optional_name(const py::handle& row) {
    if (!py::isinstance<py::dict>(row)) {
        throw py::type_error("a row is a dict, not " +
                             std::string(py::str(py::type::of(row).attr("__name__"))));
    }
    auto d = py::reinterpret_borrow<py::dict>(row);
    if (!d.contains("_name") || d["_name"].is_none()) {
        return {};
    }
    return d["_name"].cast<std::string>();
}

ACSet from_dict(const schema::SchemaPtr& schema, const py::dict& data) {
    const auto& s = *schema;
    ACSet x(schema);
    // First every part and variable, so that rows may refer to parts listed after them.
    std::vector<std::pair<ObId, py::list>> tables;
    for (auto [key, rows] : data) {
        auto name = key.cast<std::string>();
        auto g = s.find(name);
        if (!g ||
            (g->kind != schema::GeneratorKind::Ob && g->kind != schema::GeneratorKind::AttrType)) {
            throw py::key_error("schema " + s.name() + " has no object or attribute type '" + name +
                                "'");
        }
        auto list = py::list(py::reinterpret_borrow<py::object>(rows));
        if (g->kind == schema::GeneratorKind::AttrType) {
            for (auto row : list) {
                x.add_var(AttrTypeId(g->index), optional_name(row));
            }
            continue;
        }
        ObId ob(g->index);
        for (auto row : list) {
            x.add_part(ob, optional_name(row));
        }
        tables.emplace_back(ob, list);
    }
    std::vector<std::optional<NameIndex>> indexes(s.num_obs());
    for (const auto& [ob, rows] : tables) {
        Part p = 0;
        for (auto row : rows) {
            for (auto [key, value] : py::reinterpret_borrow<py::dict>(row)) {
                auto k = key.cast<std::string>();
                if (k == "_name") {
                    continue;
                }
                const NameIndex* names = nullptr;
                if (auto f = s.find_hom(k); f && py::isinstance<py::str>(value)) {
                    auto& idx = indexes[s.hom(*f).codom.index()];
                    if (!idx) {
                        idx = name_index(x, s.hom(*f).codom);
                    }
                    names = &*idx;
                }
                set_cell(x, ob, p, k, value, names);
            }
            ++p;
        }
    }
    return x;
}

py::dict columns(const ACSet& x, ObId ob) {
    const auto& s = x.schema();
    py::dict out;
    py::list names;
    for (Part p = 0; p < x.num_parts(ob); ++p) {
        names.append(name_or_none(x.part_name(ob, p)));
    }
    out["_name"] = names;
    for (HomId f : s.homs_from(ob)) {
        py::list col;
        for (Part q : x.column(f)) {
            col.append(q == kNoPart ? py::object(py::none()) : py::int_(q));
        }
        out[py::str(s.hom(f).name)] = col;
    }
    for (AttrId a : s.attrs_from(ob)) {
        py::list col;
        for (const auto& v : x.column(a)) {
            col.append(to_python(x, s.attr(a).codom, v));
        }
        out[py::str(s.attr(a).name)] = col;
    }
    return out;
}

PyState state_from_json(const PySchema& schema, const std::string& text,
                        const std::string& filename) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer(filename, text);
    std::optional<ACSet> x;
    {
        py::gil_scoped_release release;
        x = json::read_acset(schema.ptr, file, sources, sink);
    }
    if (!x || sink.has_errors()) {
        throw error_from(sources, sink);
    }
    return PyState::owned(std::move(*x));
}

void bind_reading(py::class_<PyState>& c) {
    c.def_property_readonly("schema",
                            [](const PyState& x) { return PySchema{x.get().schema_ptr()}; })
        .def_property("name", &PyState::name, &PyState::set_name,
                      "The declaration's name when loaded from a module ('' otherwise).")
        .def(
            "nparts",
            [](const PyState& x, const std::string& ob) {
                return x.get().num_parts(ob_named(x.get().schema(), ob));
            },
            py::arg("ob"), "The number of parts of an object.")
        .def(
            "parts",
            [](const PyState& x, const std::string& ob) {
                return py::module_::import("builtins")
                    .attr("range")(x.get().num_parts(ob_named(x.get().schema(), ob)));
            },
            py::arg("ob"), "The parts of an object: range(nparts(ob)).")
        .def(
            "part_names",
            [](const PyState& x, const std::string& ob) {
                ObId o = ob_named(x.get().schema(), ob);
                py::list out;
                for (Part p = 0; p < x.get().num_parts(o); ++p) {
                    out.append(name_or_none(x.get().part_name(o, p)));
                }
                return out;
            },
            py::arg("ob"), "The name of each part of an object (None for an unnamed part).")
        .def(
            "find_part",
            [](const PyState& x, const std::string& ob, const std::string& name) {
                return x.get().find_part(ob_named(x.get().schema(), ob), name);
            },
            py::arg("ob"), py::arg("name"), "The first part of ob with this name, or None.")
        .def(
            "label",
            [](const PyState& x, const std::string& ob, const py::handle& part) {
                ObId o = ob_named(x.get().schema(), ob);
                return x.get().part_label(o, part_arg(x.get(), o, part));
            },
            py::arg("ob"), py::arg("part"),
            "The part's name, or '#k' (1-based, as the command line prints) when it has none.")
        .def(
            "subpart",
            [](const PyState& x, const std::string& f, const py::handle& part) -> py::object {
                const auto& s = x.get().schema();
                auto g = hom_or_attr_named(s, f);
                if (g.kind == schema::GeneratorKind::Hom) {
                    HomId h(g.index);
                    Part q = x.get().subpart(h, part_arg(x.get(), s.hom(h).dom, part));
                    return q == kNoPart ? py::object(py::none()) : py::int_(q);
                }
                AttrId a(g.index);
                return to_python(x.get(), s.attr(a).codom,
                                 x.get().subpart(a, part_arg(x.get(), s.attr(a).dom, part)));
            },
            py::arg("f"), py::arg("part"),
            "The value of a hom (a part index, None when unset) or an attribute (bool, int, "
            "float, str, Var, or None when unset) at a part.")
        .def(
            "incident",
            [](const PyState& x, const std::string& f, const py::handle& part) {
                const auto& s = x.get().schema();
                HomId h = hom_named(s, f);
                auto span = x.get().incident(h, part_arg(x.get(), s.hom(h).codom, part));
                std::vector<Part> out(span.begin(), span.end());
                std::sort(out.begin(), out.end());
                return out;
            },
            py::arg("f"), py::arg("part"), "The parts p with f(p) == part, in increasing order.")
        .def(
            "variables",
            [](const PyState& x, const std::string& type) {
                auto t = attr_type_named(x.get().schema(), type);
                std::vector<PyVar> out;
                for (std::uint32_t j = 0; j < x.get().num_vars(t); ++j) {
                    out.push_back({type, j, std::string(x.get().var_name(t, j))});
                }
                return out;
            },
            py::arg("type"), "The attribute variables of an attribute type.")
        .def(
            "total_parts", [](const PyState& x) { return x.get().total_parts(); },
            "The number of parts over all objects.")
        .def(
            "to_dict", [](const PyState& x) { return to_dict(x.get()); },
            R"doc(The state as plain Python data: {object: [row, ...]} in schema order, each row
{"_name": name or None, hom: part index or None, attribute: value}, then {attribute type:
[{"_name": ...}, ...]} for the types that have variables. State.from_dict reads it back.)doc")
        .def(
            "columns",
            [](const PyState& x, const std::string& ob) {
                return columns(x.get(), ob_named(x.get().schema(), ob));
            },
            py::arg("ob"),
            "The object's table as {column: list}: '_name', then each hom (part indexes, None "
            "when unset), then each attribute.");
}

void bind_writing(py::class_<PyState>& c) {
    c.def(
         "add_part",
         [](PyState& st, const std::string& ob, const std::optional<std::string>& name,
            const py::kwargs& values) {
             auto& x = st.mut();
             ObId o = ob_named(x.schema(), ob);
             Part p = x.add_part(o, name.value_or(""));
             for (auto [k, v] : values) {
                 set_cell(x, o, p, k.cast<std::string>(), v);
             }
             return p;
         },
         py::arg("ob"), py::arg("name") = py::none(),
         "Adds a part (optionally named), with hom and attribute values given as keywords "
         "(a hom's value is a part index or name); returns its index.")
        .def(
            "set_subpart",
            [](PyState& st, const std::string& f, const py::handle& part, const py::handle& v) {
                auto& x = st.mut();
                const auto& s = x.schema();
                auto g = hom_or_attr_named(s, f);
                ObId dom = g.kind == schema::GeneratorKind::Hom ? s.hom(HomId(g.index)).dom
                                                                : s.attr(AttrId(g.index)).dom;
                set_cell(x, dom, part_arg(x, dom, part), f, v);
            },
            py::arg("f"), py::arg("part"), py::arg("value"),
            "Sets a hom (to a part index or name; None unsets) or an attribute at a part.")
        .def(
            "set_part_name",
            [](PyState& st, const std::string& ob, const py::handle& part,
               const std::string& name) {
                auto& x = st.mut();
                ObId o = ob_named(x.schema(), ob);
                x.set_part_name(o, part_arg(x, o, part), name);
            },
            py::arg("ob"), py::arg("part"), py::arg("name"), "Names a part ('' unnames it).")
        .def(
            "remove_part",
            [](PyState& st, const std::string& ob, const py::handle& part) -> std::optional<Part> {
                auto& x = st.mut();
                ObId o = ob_named(x.schema(), ob);
                Part moved = x.remove_part(o, part_arg(x, o, part));
                return moved == kNoPart ? std::nullopt : std::optional<Part>(moved);
            },
            py::arg("ob"), py::arg("part"),
            "Removes a part by pop-and-swap (Catlab's rem_part!): the last part moves into its "
            "place and references to the removed part become unset. Returns the former index "
            "of the part now at that place, or None when it was the last.")
        .def(
            "add_var",
            [](PyState& st, const std::string& type, const std::string& name) {
                auto& x = st.mut();
                auto t = attr_type_named(x.schema(), type);
                auto v = x.add_var(t, name);
                return PyVar{type, v.var_index(), name};
            },
            py::arg("type"), py::arg("name") = "", "Adds an attribute variable (an unknown).");
}

void bind_output(py::class_<PyState>& c) {
    c.def(
         "to_json",
         [](const PyState& x, bool pretty) { return json::write_acset(x.get(), pretty); },
         py::arg("pretty") = false, "Catlab's ACSet JSON.")
        .def_static("from_json", &state_from_json, py::arg("schema"), py::arg("text"),
                    py::arg("filename") = "<json>",
                    "Reads Catlab's ACSet JSON on a schema; raises CatplanError with located "
                    "diagnostics.")
        .def(
            "to_dot",
            [](const PyState& x, bool left_to_right) {
                dot::DotOptions o;
                o.left_to_right = left_to_right;
                return dot::state_to_dot(x.get(), x.name().empty() ? "State" : x.name(), o);
            },
            py::arg("left_to_right") = false, "A Graphviz DOT picture of the state.")
        .def(
            "to_text",
            [](const PyState& x, const std::optional<std::string>& name) {
                return lang::print_instance(
                    x.get(), name.value_or(x.name().empty() ? std::string("State") : x.name()));
            },
            py::arg("name") = py::none(), "The state in @acset_colim form, loadable again.")
        .def("__str__", [](const PyState& x) { return acset::to_tables(x.get()); })
        .def("__repr__",
             [](const PyState& x) {
                 const auto& s = x.get().schema();
                 std::string counts;
                 for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
                     auto n = x.get().num_parts(ObId(i));
                     if (n > 0) {
                         counts += (counts.empty() ? "" : ", ") + s.ob(ObId(i)).name + " " +
                                   std::to_string(n);
                     }
                 }
                 return "<State " + (x.name().empty() ? std::string() : x.name() + " ") + "on " +
                        s.name() + ": " + std::to_string(x.get().total_parts()) + " parts" +
                        (counts.empty() ? std::string() : " (" + counts + ")") + ">";
             })
        .def(
            "copy", [](const PyState& x) { return PyState::owned(x.get(), x.name()); },
            "An independent copy.")
        .def("__copy__", [](const PyState& x) { return PyState::owned(x.get(), x.name()); })
        .def("__deepcopy__",
             [](const PyState& x, const py::handle&) { return PyState::owned(x.get(), x.name()); })
        .def(
            "__eq__", [](const PyState& a, const PyState& b) { return a.get() == b.get(); },
            "Exact equality of parts, columns and variables (names are ignored).")
        .def("is_isomorphic", &isomorphic, py::arg("other"),
             "Whether the states are isomorphic (names ignored).");
}

} // namespace

void bind_state(py::module_& m) {
    py::class_<PyState> c(m, "State", R"doc(
A state: an attributed C-set on a schema (Catlab's ACSet). Each object has parts 0..n-1; a hom
maps each part to a part of its codomain (or is unset); an attribute gives each part a value:
bool, int, float or str, a Var (an unknown), or None (unset). Parts may have names ("A",
"gripper"), which plans use to refer to them.

States from a module or a result can be changed freely: the first change copies them.)doc");
    c.def(py::init([](const PySchema& s, const std::string& name) {
              return PyState::empty(s.ptr, name);
          }),
          py::arg("schema"), py::arg("name") = "", "An empty state on a schema.")
        .def_static(
            "from_dict",
            [](const PySchema& s, const py::dict& data, const std::string& name) {
                return PyState::owned(from_dict(s.ptr, data), name);
            },
            py::arg("schema"), py::arg("data"), py::arg("name") = "",
            R"doc(A state from plain Python data, as to_dict writes it: {object: [row, ...]},
each row a dict with an optional "_name" and hom and attribute values, a hom's value being a
part index or the name of a part of its codomain (rows may refer to parts listed later).)doc");
    bind_reading(c);
    bind_writing(c);
    bind_output(c);
}

} // namespace catplan::python
