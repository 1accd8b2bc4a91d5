// Names, parts and attribute values between Python and the library.

#include <pybind11/operators.h>

#include "common.hpp"

namespace catplan::python {

namespace {

[[noreturn]] void no_such(const schema::Schema& s, std::string_view what, const std::string& name) {
    throw py::key_error("schema " + s.name() + " has no " + std::string(what) + " '" + name + "'");
}

} // namespace

ObId ob_named(const schema::Schema& s, const std::string& name) {
    if (auto x = s.find_ob(name)) {
        return *x;
    }
    no_such(s, "object", name);
}

HomId hom_named(const schema::Schema& s, const std::string& name) {
    if (auto f = s.find_hom(name)) {
        return *f;
    }
    no_such(s, "hom", name);
}

AttrTypeId attr_type_named(const schema::Schema& s, const std::string& name) {
    if (auto t = s.find_attr_type(name)) {
        return *t;
    }
    no_such(s, "attribute type", name);
}

schema::Generator hom_or_attr_named(const schema::Schema& s, const std::string& name) {
    auto g = s.find(name);
    if (!g || (g->kind != schema::GeneratorKind::Hom && g->kind != schema::GeneratorKind::Attr)) {
        no_such(s, "hom or attribute", name);
    }
    return *g;
}

Part part_arg(const acset::ACSet& x, ObId ob, const py::handle& part) {
    const auto& ob_name = x.schema().ob(ob).name;
    if (py::isinstance<py::str>(part)) {
        auto name = part.cast<std::string>();
        if (auto p = x.find_part(ob, name)) {
            return *p;
        }
        throw py::key_error("no part of " + ob_name + " is named '" + name + "'");
    }
    if (!py::isinstance<py::int_>(part) || py::isinstance<py::bool_>(part)) {
        throw py::type_error("a part of " + ob_name + " is an int (0-based) or a name, not " +
                             std::string(py::str(py::type::of(part).attr("__name__"))));
    }
    auto i = part.cast<long long>();
    auto n = static_cast<long long>(x.num_parts(ob));
    if (i < 0) {
        i += n;
    }
    if (i < 0 || i >= n) {
        throw py::index_error(ob_name + " has " + std::to_string(n) + " parts; no part " +
                              std::string(py::str(part)));
    }
    return static_cast<Part>(i);
}

void require_same_schema(const acset::ACSet& x, const acset::ACSet& y) {
    const auto& s = x.schema();
    const auto& t = y.schema();
    if (&s == &t || (s.num_obs() == t.num_obs() && s.num_homs() == t.num_homs() &&
                     s.num_attrs() == t.num_attrs() && s.num_attr_types() == t.num_attr_types())) {
        return;
    }
    throw py::value_error("the states are on different schemas (" + s.name() + ", " + t.name() +
                          ")");
}

py::object to_python(const acset::ACSet& x, AttrTypeId t, const acset::Value& v) {
    using Tag = acset::Value::Tag;
    switch (v.tag()) {
    case Tag::Unset:
        return py::none();
    case Tag::Var:
        return py::cast(PyVar{x.schema().attr_type(t).name, v.var_index(),
                              std::string(x.var_name(t, v.var_index()))});
    case Tag::Bool:
        return py::bool_(v.as_bool());
    case Tag::Int:
        return py::int_(v.as_int());
    case Tag::Float:
        return py::float_(v.as_float());
    case Tag::String:
        return py::str(std::string(v.as_string()));
    }
    return py::none();
}

acset::Value from_python(const acset::ACSet& x, AttrTypeId t, const py::handle& v) {
    using schema::ValueKind;
    const auto& info = x.schema().attr_type(t);
    auto kind = info.kind;
    auto wrong = [&](std::string_view given) {
        return py::type_error("attribute type " + info.name + " holds " +
                              std::string(schema::to_string(kind)) + " values, not " +
                              std::string(given));
    };
    if (v.is_none()) {
        return {};
    }
    if (py::isinstance<PyVar>(v)) {
        const auto& var = v.cast<const PyVar&>();
        if (var.type != info.name) {
            throw py::type_error("variable of " + var.type + " given for attribute type " +
                                 info.name);
        }
        if (var.index >= x.num_vars(t)) {
            throw py::index_error("the state has " + std::to_string(x.num_vars(t)) +
                                  " variables of " + info.name + "; no variable " +
                                  std::to_string(var.index));
        }
        return acset::Value::var(var.index);
    }
    if (py::isinstance<py::bool_>(v)) {
        if (kind != ValueKind::Bool && kind != ValueKind::Unknown) {
            throw wrong("bool");
        }
        return acset::Value::boolean(v.cast<bool>());
    }
    if (py::isinstance<py::int_>(v)) {
        if (kind == ValueKind::Float) {
            return acset::Value::real(v.cast<double>());
        }
        if (kind != ValueKind::Int && kind != ValueKind::Unknown) {
            throw wrong("int");
        }
        return acset::Value::integer(v.cast<std::int64_t>());
    }
    if (py::isinstance<py::float_>(v)) {
        if (kind != ValueKind::Float && kind != ValueKind::Unknown) {
            throw wrong("float");
        }
        return acset::Value::real(v.cast<double>());
    }
    if (py::isinstance<py::str>(v)) {
        if (kind != ValueKind::String && kind != ValueKind::Unknown) {
            throw wrong("str");
        }
        return acset::Value::string(v.cast<std::string>());
    }
    // numpy scalars and other numbers: by what they convert to.
    if (py::hasattr(v, "dtype") && py::hasattr(v, "item")) {
        return from_python(x, t, v.attr("item")());
    }
    throw wrong(std::string(py::str(py::type::of(v).attr("__name__"))));
}

void bind_values(py::module_& m) {
    py::class_<PyVar>(m, "Var", R"doc(
An attribute variable of a state (Catlab's ``AttrVar``): an unknown value, such as the colour of
the paper's "empty" block. A variable never equals a concrete value.

``type`` is the attribute type's name, ``index`` its number in the state (0-based; the command
line prints ``?1`` for index 0) and ``name`` its name or "".)doc")
        .def(py::init([](std::string type, std::uint32_t index, std::string name) {
                 return PyVar{std::move(type), index, std::move(name)};
             }),
             py::arg("type"), py::arg("index"), py::arg("name") = "")
        .def_readonly("type", &PyVar::type)
        .def_readonly("index", &PyVar::index)
        .def_readonly("name", &PyVar::name)
        .def("__eq__",
             [](const PyVar& a, const PyVar& b) { return a.type == b.type && a.index == b.index; })
        .def("__hash__", [](const PyVar& v) { return py::hash(py::make_tuple(v.type, v.index)); })
        .def("__repr__", [](const PyVar& v) {
            return "Var(" + v.type + ", " + std::to_string(v.index) +
                   (v.name.empty() ? std::string() : ", '" + v.name + "'") + ")";
        });
}

} // namespace catplan::python
