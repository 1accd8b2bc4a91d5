// catplan.Morphism and the homomorphism search between states (catplan.homs, hom, count_homs,
// is_isomorphic).

#include "catplan/dot/dot.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/hom/isomorphism.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

py::dict components(const PyMorphism& f) {
    py::dict out;
    const schema::Schema* s = f.dom ? &f.dom->schema() : nullptr;
    for (std::size_t i = 0; i < f.m.components.size(); ++i) {
        auto key =
            s != nullptr ? s->ob(ObId(static_cast<std::uint32_t>(i))).name : std::to_string(i);
        out[py::str(key)] = f.m.components[i];
    }
    return out;
}

py::dict var_components(const PyMorphism& f) {
    py::dict out;
    if (!f.dom || !f.codom) {
        return out;
    }
    const auto& s = f.dom->schema();
    for (std::size_t i = 0; i < f.m.var_components.size(); ++i) {
        AttrTypeId t(static_cast<std::uint32_t>(i));
        if (f.m.var_components[i].empty()) {
            continue;
        }
        py::list images;
        for (const auto& v : f.m.var_components[i]) {
            images.append(to_python(*f.codom, t, v));
        }
        out[py::str(s.attr_type(t).name)] = images;
    }
    return out;
}

const PyMorphism& with_ends(const PyMorphism& f) {
    if (!f.dom || !f.codom) {
        throw py::value_error("this morphism's domain and codomain are not known");
    }
    return f;
}

py::dict bindings(const PyMorphism& f) {
    const auto& g = with_ends(f);
    const auto& s = g.dom->schema();
    py::dict out;
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        ObId ob(i);
        for (Part p = 0; p < g.dom->num_parts(ob); ++p) {
            auto key = g.dom->part_label(ob, p);
            if (!out.contains(key)) {
                out[py::str(key)] = g.codom->part_label(ob, g.m(ob, p));
            }
        }
    }
    return out;
}

void bind_morphism(py::module_& m) {
    py::class_<PyMorphism>(m, "Morphism", R"doc(
A morphism of states f : dom -> codom (a natural transformation): for each object, the image of
each part of dom, and for each attribute type, the image of each variable of dom. A match of a
rule is a morphism from its Pre into a state.)doc")
        .def_property_readonly("components", &components,
                               "{object: [image of part 0, image of part 1, ...]}.")
        .def_property_readonly("var_components", &var_components,
                               "{attribute type: [image of variable 0, ...]} (values or Var).")
        .def_property_readonly("dom",
                               [](const PyMorphism& f) -> std::optional<PyState> {
                                   return f.dom ? std::optional<PyState>(PyState(f.dom))
                                                : std::nullopt;
                               })
        .def_property_readonly("codom",
                               [](const PyMorphism& f) -> std::optional<PyState> {
                                   return f.codom ? std::optional<PyState>(PyState(f.codom))
                                                  : std::nullopt;
                               })
        .def(
            "__call__",
            [](const PyMorphism& f, const std::string& ob, const py::handle& part) {
                const auto& g = with_ends(f);
                ObId o = ob_named(g.dom->schema(), ob);
                return g.m(o, part_arg(*g.dom, o, part));
            },
            py::arg("ob"), py::arg("part"), "The image of a part (index or name) of dom.")
        .def("bindings", &bindings,
             "{label of a part of dom: label of its image}, each label once (the first object "
             "that has it), as names or #k.")
        .def(
            "is_monic",
            [](const PyMorphism& f) {
                const auto& g = with_ends(f);
                return hom::is_monic(g.m, *g.dom, *g.codom);
            },
            "Whether every object component is injective.")
        .def("is_iso",
             [](const PyMorphism& f) {
                 const auto& g = with_ends(f);
                 return hom::is_iso(g.m, *g.dom, *g.codom);
             })
        .def(
            "naturality_failures",
            [](const PyMorphism& f) {
                const auto& g = with_ends(f);
                std::vector<std::string> out;
                for (const auto& failure : hom::naturality_failures(g.m, *g.dom, *g.codom)) {
                    out.push_back(hom::describe(failure, *g.dom, *g.codom));
                }
                return out;
            },
            "Every square that does not commute, in words (empty for a morphism).")
        .def(
            "to_dot",
            [](const PyMorphism& f, const std::string& name) {
                const auto& g = with_ends(f);
                return dot::morphism_to_dot(g.m, *g.dom, *g.codom, name);
            },
            py::arg("name") = "f", "A Graphviz DOT picture: dom and codom side by side.")
        .def("__eq__", [](const PyMorphism& a, const PyMorphism& b) { return a.m == b.m; })
        .def("__repr__", [](const PyMorphism& f) {
            if (!f.dom || !f.codom) {
                return std::string("<Morphism>");
            }
            std::string text;
            for (auto [k, v] : bindings(f)) {
                text += (text.empty() ? "" : ", ") + std::string(py::str(k)) + " ↦ " +
                        std::string(py::str(v));
            }
            return "<Morphism " + text + ">";
        });
}

/// Options from the Python keywords; initial is {object: {dom part: codom part}}.
hom::HomSearchOptions hom_options(const acset::ACSet& x, const acset::ACSet& y, bool monic,
                                  bool iso, const py::object& initial) {
    require_same_schema(x, y);
    hom::HomSearchOptions o;
    o.monic_all = monic;
    o.iso = iso;
    if (!initial.is_none()) {
        for (auto [ob, pairs] : initial.cast<py::dict>()) {
            ObId o_id = ob_named(x.schema(), ob.cast<std::string>());
            for (auto [d, c] : pairs.cast<py::dict>()) {
                o.bind(o_id, part_arg(x, o_id, d), part_arg(y, o_id, c));
            }
        }
    }
    return o;
}

/// Runs the search without the GIL, interruptible; fn gets each morphism and returns whether
/// to go on.
hom::HomSearchResult search(const acset::ACSet& x, const acset::ACSet& y, hom::HomSearchOptions o,
                            const std::function<bool(const hom::ACSetMorphism&)>& fn) {
    hom::HomSearchResult r;
    Interruptible inter;
    o.accept = [&](ObId, Part, Part) { return !inter.poll(); };
    r = hom::for_each_homomorphism(
        x, y, o, [&](const hom::ACSetMorphism& f) { return !inter.poll() && fn(f); });
    inter.finish();
    if (!r.error.empty()) {
        throw error_from(r.error);
    }
    return r;
}

std::vector<PyMorphism> homs(PyState& xs, PyState& ys, bool monic, bool iso, std::uint64_t max,
                             const py::object& initial) {
    auto x = xs.share();
    auto y = ys.share();
    auto o = hom_options(*x, *y, monic, iso, initial);
    std::vector<PyMorphism> out;
    search(*x, *y, std::move(o), [&](const hom::ACSetMorphism& f) {
        out.push_back(PyMorphism{f, x, y});
        return max == 0 || out.size() < max;
    });
    return out;
}

void bind_search(py::module_& m) {
    m.def("homs", &homs, py::arg("x"), py::arg("y"), py::kw_only(), py::arg("monic") = false,
          py::arg("iso") = false, py::arg("max") = 0, py::arg("initial") = py::none(),
          R"doc(Every homomorphism x -> y (at most max when max > 0), in a deterministic order.

monic: injective on every object (never on attribute values); iso: bijective, variables onto
variables. initial fixes parts in advance: {object: {part of x: part of y}}, parts as indexes
or names. Runs without the GIL; Ctrl-C interrupts it. Raises CatplanError when the hom set is
infinite (a variable of x that no attribute uses).)doc");
    m.def(
        "hom",
        [](PyState& x, PyState& y, bool monic, bool iso,
           const py::object& initial) -> std::optional<PyMorphism> {
            auto found = homs(x, y, monic, iso, 1, initial);
            return found.empty() ? std::nullopt : std::optional<PyMorphism>(found.front());
        },
        py::arg("x"), py::arg("y"), py::kw_only(), py::arg("monic") = false, py::arg("iso") = false,
        py::arg("initial") = py::none(),
        "The first homomorphism x -> y (as homs finds them), or None.");
    m.def(
        "count_homs",
        [](PyState& xs, PyState& ys, bool monic, bool iso, const py::object& initial) {
            auto x = xs.share();
            auto y = ys.share();
            std::uint64_t n = 0;
            search(*x, *y, hom_options(*x, *y, monic, iso, initial), [&](const auto&) {
                ++n;
                return true;
            });
            return n;
        },
        py::arg("x"), py::arg("y"), py::kw_only(), py::arg("monic") = false, py::arg("iso") = false,
        py::arg("initial") = py::none(),
        "The number of homomorphisms x -> y, without keeping them.");
    m.def("is_isomorphic", &isomorphic, py::arg("x"), py::arg("y"),
          "Whether x and y are isomorphic (names ignored).");
}

} // namespace

bool isomorphic(PyState& xs, PyState& ys) {
    auto x = xs.share();
    auto y = ys.share();
    require_same_schema(*x, *y);
    py::gil_scoped_release release;
    return hom::is_isomorphic(*x, *y);
}

void bind_hom(py::module_& m) {
    bind_morphism(m);
    bind_search(m);
}

} // namespace catplan::python
