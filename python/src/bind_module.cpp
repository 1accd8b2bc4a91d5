// catplan.load / loads and catplan.Module: a .cp file's declarations as Python objects (Schema,
// State, Rule, Domain, Problem, Map).

#include "catplan/dot/dot.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/describe.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

std::string_view kind_word(lang::DeclKind k) {
    switch (k) {
    case lang::DeclKind::Schema:
        return "schema";
    case lang::DeclKind::Instance:
        return "state";
    case lang::DeclKind::Rule:
        return "rule";
    case lang::DeclKind::Domain:
        return "domain";
    case lang::DeclKind::Problem:
        return "problem";
    case lang::DeclKind::Map:
        return "map";
    }
    return "declaration";
}

py::object wrap(const lang::Declaration& d) {
    switch (d.kind) {
    case lang::DeclKind::Schema:
        return py::cast(PySchema{d.schema});
    case lang::DeclKind::Instance:
        return py::cast(PyState(d.instance, d.name));
    case lang::DeclKind::Rule:
        return py::cast(PyRule{d.rule});
    case lang::DeclKind::Domain:
        return py::cast(PyDomain{d.domain});
    case lang::DeclKind::Problem:
        return py::cast(PyProblem{d.problem});
    case lang::DeclKind::Map:
        return py::cast(PyMap{d.map, d.name});
    }
    return py::none();
}

py::dict of_kind(const PyModule& m, lang::DeclKind k) {
    py::dict out;
    for (const auto& d : m.module.declarations()) {
        if (d.kind == k) {
            out[py::str(d.name)] = wrap(d);
        }
    }
    return out;
}

/// Runs one of lang's loaders without the GIL; CatplanError with every diagnostic on errors.
template <class Loader>
PyModule load_with(std::size_t max_fresh_parts, const Loader& loader) {
    auto sources = std::make_shared<SourceManager>();
    DiagnosticSink sink(*sources);
    lang::LoadOptions options;
    options.max_fresh_parts = max_fresh_parts;
    lang::Module module;
    {
        py::gil_scoped_release release;
        module = loader(*sources, sink, options);
    }
    if (sink.has_errors()) {
        throw error_from(*sources, sink);
    }
    auto warnings = diagnostics_of(*sources, sink);
    return PyModule{std::move(sources), std::move(module), std::move(warnings)};
}

PyModule load(const std::string& path, std::size_t max_fresh_parts) {
    return load_with(max_fresh_parts, [&](SourceManager& sources, DiagnosticSink& sink,
                                          const lang::LoadOptions& options) {
        return lang::load_file(path, sources, sink, options);
    });
}

PyModule loads(const std::string& text, const std::string& name, std::size_t max_fresh_parts) {
    return load_with(max_fresh_parts, [&](SourceManager& sources, DiagnosticSink& sink,
                                          const lang::LoadOptions& options) {
        return lang::load_source(name, text, sources, sink, options);
    });
}

const lang::Declaration& declaration(const PyModule& m, const std::string& name) {
    const auto* d = m.module.find(name);
    if (d == nullptr) {
        throw py::key_error("the module declares no '" + name + "'");
    }
    return *d;
}

/// A state that lives inside a library object, kept alive by that object's owner.
template <class Owner>
PyState inner_state(const std::shared_ptr<Owner>& owner, const acset::ACSet& x,
                    std::string name = {}) {
    return PyState(std::shared_ptr<const acset::ACSet>(owner, &x), std::move(name));
}

void bind_module_class(py::module_& m) {
    py::class_<PyModule>(m, "Module", R"doc(
The declarations of a loaded file (and of the files it imports), by name: ``module["Initial"]``
is a State, ``module["Blocksworld"]`` a Domain, and so on. Iterating gives the names in load
order, imports first.)doc")
        .def("__getitem__", [](const PyModule& self,
                               const std::string& name) { return wrap(declaration(self, name)); })
        .def("__contains__",
             [](const PyModule& self, const std::string& name) {
                 return self.module.find(name) != nullptr;
             })
        .def("__len__", [](const PyModule& self) { return self.module.declarations().size(); })
        .def("__iter__",
             [](const PyModule& self) {
                 py::list names;
                 for (const auto& d : self.module.declarations()) {
                     names.append(d.name);
                 }
                 return py::iter(names);
             })
        .def(
            "get",
            [](const PyModule& self, const std::string& name) -> py::object {
                const auto* d = self.module.find(name);
                return d == nullptr ? py::object(py::none()) : wrap(*d);
            },
            py::arg("name"), "The declaration with this name, or None.")
        .def(
            "kind",
            [](const PyModule& self, const std::string& name) {
                return std::string(kind_word(declaration(self, name).kind));
            },
            py::arg("name"),
            "What a name declares: 'schema', 'state', 'rule', 'domain', 'problem' or 'map'.")
        .def(
            "summary",
            [](const PyModule& self, const std::string& name) {
                return lang::summarize(declaration(self, name));
            },
            py::arg("name"), "The one-line summary `catplan check` prints for a declaration.")
        .def_property_readonly(
            "names",
            [](const PyModule& self) {
                std::vector<std::string> out;
                for (const auto& d : self.module.declarations()) {
                    out.push_back(d.name);
                }
                return out;
            },
            "Every declared name, in load order (imports first).")
        .def_property_readonly(
            "own_names",
            [](const PyModule& self) {
                std::vector<std::string> out;
                for (const auto& d : self.module.declarations()) {
                    if (!d.imported) {
                        out.push_back(d.name);
                    }
                }
                return out;
            },
            "The names declared in the loaded file itself (not imported).")
        .def_property_readonly(
            "schemas", [](const PyModule& self) { return of_kind(self, lang::DeclKind::Schema); })
        .def_property_readonly(
            "states", [](const PyModule& self) { return of_kind(self, lang::DeclKind::Instance); })
        .def_property_readonly(
            "rules", [](const PyModule& self) { return of_kind(self, lang::DeclKind::Rule); })
        .def_property_readonly(
            "domains", [](const PyModule& self) { return of_kind(self, lang::DeclKind::Domain); })
        .def_property_readonly(
            "problems", [](const PyModule& self) { return of_kind(self, lang::DeclKind::Problem); })
        .def_property_readonly(
            "maps", [](const PyModule& self) { return of_kind(self, lang::DeclKind::Map); })
        .def_readonly("warnings", &PyModule::warnings, "Warnings met while loading (Diagnostic).")
        .def("__repr__", [](const PyModule& self) {
            return "<Module: " + std::to_string(self.module.declarations().size()) +
                   " declarations>";
        });

    m.def("load", &load, py::arg("path"), py::arg("max_fresh_parts") = 100000,
          R"doc(Loads a .cp file and the files it imports into a Module.

Raises CatplanError carrying every located diagnostic when the file has errors (or cannot be
read). max_fresh_parts bounds the parts a free instance may create on a cyclic schema.)doc");
    m.def("loads", &loads, py::arg("text"), py::arg("name") = "<string>",
          py::arg("max_fresh_parts") = 100000,
          "Like load, for text in memory; name is used in diagnostics and anchors relative "
          "@imports.");
}

void bind_rule(py::module_& m) {
    py::class_<PyRule>(m, "Rule", R"doc(
An action as a DPO rewrite rule Pre <-l- Keep -r-> Eff (L <- K -> R): the parts of Pre outside
Keep are deleted, the parts of Eff outside Keep created. Its parameters are the named generators
of Pre, bound by a plan step such as ``unstack(E, D)``.)doc")
        .def_property_readonly("name", [](const PyRule& r) { return r.ptr->name; })
        .def_property_readonly(
            "parameters",
            [](const PyRule& r) {
                py::list out;
                for (const auto& p : r.ptr->parameters) {
                    out.append(py::make_tuple(p.name, r.ptr->L.schema().ob(p.ob).name));
                }
                return out;
            },
            "The parameters as (name, object) tuples, in order.")
        .def_property_readonly("schema",
                               [](const PyRule& r) { return PySchema{r.ptr->L.schema_ptr()}; })
        .def_property_readonly(
            "pre", [](const PyRule& r) { return inner_state(r.ptr, r.ptr->L, "Pre"); },
            "L, the precondition.")
        .def_property_readonly(
            "keep", [](const PyRule& r) { return inner_state(r.ptr, r.ptr->K, "Keep"); },
            "K, what the rule keeps.")
        .def_property_readonly(
            "eff", [](const PyRule& r) { return inner_state(r.ptr, r.ptr->R, "Eff"); },
            "R, the effect.")
        .def_property_readonly(
            "l",
            [](const PyRule& r) {
                return PyMorphism{r.ptr->l, {r.ptr, &r.ptr->K}, {r.ptr, &r.ptr->L}};
            },
            "The morphism Keep -> Pre.")
        .def_property_readonly(
            "r",
            [](const PyRule& r) {
                return PyMorphism{r.ptr->r, {r.ptr, &r.ptr->K}, {r.ptr, &r.ptr->R}};
            },
            "The morphism Keep -> Eff.")
        .def_property_readonly(
            "conditions",
            [](const PyRule& r) {
                py::list out;
                for (const auto& c : r.ptr->conditions) {
                    out.append(py::make_tuple(c.name, c.negative ? "negative" : "positive",
                                              inner_state(r.ptr, c.n_state, c.name)));
                }
                return out;
            },
            "The application conditions as (name, 'negative' or 'positive', state N).")
        .def_property_readonly("semantics",
                               [](const PyRule& r) {
                                   return r.ptr->semantics == rewrite::Semantics::DPO ? "DPO"
                                                                                      : "SPO";
                               })
        .def(
            "to_dot", [](const PyRule& r) { return dot::rule_to_dot(*r.ptr); },
            "A Graphviz DOT picture of Pre <- Keep -> Eff.")
        .def("__str__", [](const PyRule& r) { return lang::summarize_rule(*r.ptr); })
        .def("__repr__",
             [](const PyRule& r) { return "<Rule " + lang::summarize_rule(*r.ptr) + ">"; });
}

void bind_domain_problem(py::module_& m) {
    py::class_<PyDomain>(m, "Domain", "A planning domain: a schema and named rules (actions).")
        .def_property_readonly("name", [](const PyDomain& d) { return d.ptr->name; })
        .def_property_readonly("schema", [](const PyDomain& d) { return PySchema{d.ptr->schema}; })
        .def_property_readonly("rules",
                               [](const PyDomain& d) {
                                   std::vector<PyRule> out;
                                   for (const auto& r : d.ptr->rules) {
                                       out.push_back(PyRule{r});
                                   }
                                   return out;
                               })
        .def(
            "rule",
            [](const PyDomain& d, const std::string& name) {
                for (const auto& r : d.ptr->rules) {
                    if (r->name == name) {
                        return PyRule{r};
                    }
                }
                throw py::key_error("domain " + d.ptr->name + " has no rule '" + name + "'");
            },
            py::arg("name"))
        .def("__len__", [](const PyDomain& d) { return d.ptr->rules.size(); })
        .def("__repr__", [](const PyDomain& d) {
            std::string names;
            for (const auto& r : d.ptr->rules) {
                names += (names.empty() ? "" : ", ") + r->name;
            }
            return "<Domain " + d.ptr->name + " (" + d.ptr->schema->name() + "): " + names + ">";
        });

    py::class_<PyProblem>(m, "Problem", "A planning problem: a domain, an initial state, a goal.")
        .def(py::init(
                 [](const PyDomain& d, PyState& initial, PyState& goal, const std::string& name) {
                     for (const auto* x : {&initial, &goal}) {
                         if (x->get().schema_ptr() != d.ptr->schema) {
                             throw py::value_error("a state on " + x->get().schema().name() +
                                                   " cannot be a problem of domain " + d.ptr->name +
                                                   " on " + d.ptr->schema->name());
                         }
                     }
                     auto p = std::make_shared<plan::Problem>();
                     p->name = name;
                     p->domain = d.ptr;
                     p->initial = initial.share();
                     p->goal = goal.share();
                     return PyProblem{p};
                 }),
             py::arg("domain"), py::arg("initial"), py::arg("goal"), py::arg("name") = "Problem",
             "A problem of a domain; both states must be on the domain's schema (the same "
             "Schema object).")
        .def_property_readonly("name", [](const PyProblem& p) { return p.ptr->name; })
        .def_property_readonly("domain", [](const PyProblem& p) { return PyDomain{p.ptr->domain}; })
        .def_property_readonly(
            "initial", [](const PyProblem& p) { return PyState(p.ptr->initial, "initial"); })
        .def_property_readonly("goal",
                               [](const PyProblem& p) { return PyState(p.ptr->goal, "goal"); })
        .def("__repr__", [](const PyProblem& p) {
            return "<Problem " + p.ptr->name + " (" + p.ptr->domain->name + ")>";
        });
}

} // namespace

void bind_module(py::module_& m) {
    bind_module_class(m);
    bind_rule(m);
    bind_domain_problem(m);
}

} // namespace catplan::python
