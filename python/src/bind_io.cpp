// PDDL in and out: catplan.load_pddl / loads_pddl (a PDDL domain and problem as a catplan domain
// and problem), IPC plans, export_pddl.

#include "catplan/pddl/export.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/actions.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

/// An imported PDDL domain (and problem).
struct PyPddl {
    std::shared_ptr<const pddl::Import> im;
    std::vector<PyDiagnostic> warnings; ///< e.g. a requirement read only as far as catplan goes
};

/// Parses and imports; file ids are those of domain and problem text registered in sources.
PyPddl import(SourceManager& sources, DiagnosticSink& sink, std::uint32_t domain_file,
              std::optional<std::uint32_t> problem_file) {
    std::optional<pddl::Import> im;
    {
        py::gil_scoped_release release;
        auto domain = pddl::parse_domain(domain_file, sources, sink);
        if (domain && !sink.has_errors()) {
            std::optional<pddl::Problem> problem;
            if (problem_file) {
                problem = pddl::parse_problem(*problem_file, *domain, sources, sink);
            }
            if (!sink.has_errors() && (!problem_file || problem)) {
                im = pddl::import_pddl(*domain, problem ? &*problem : nullptr, sink);
            }
        }
    }
    if (!im || sink.has_errors()) {
        throw error_from(sources, sink);
    }
    return PyPddl{std::make_shared<const pddl::Import>(std::move(*im)),
                  diagnostics_of(sources, sink)};
}

std::uint32_t read_file(SourceManager& sources, DiagnosticSink& sink, const std::string& path) {
    auto id = sources.add_file(path);
    if (!id) {
        sink.error("cannot read '" + path + "'");
        throw error_from(sources, sink);
    }
    return *id;
}

PyPddl load_pddl(const std::string& domain, const std::optional<std::string>& problem) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto d = read_file(sources, sink, domain);
    std::optional<std::uint32_t> p;
    if (problem) {
        p = read_file(sources, sink, *problem);
    }
    return import(sources, sink, d, p);
}

PyPddl loads_pddl(const std::string& domain, const std::optional<std::string>& problem) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto d = sources.add_buffer("<domain>", domain);
    std::optional<std::uint32_t> p;
    if (problem) {
        p = sources.add_buffer("<problem>", *problem);
    }
    return import(sources, sink, d, p);
}

pddl::IpcPlan ipc_plan(const std::string& text, const std::string& filename) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer(filename, text);
    auto p = pddl::parse_ipc_plan(file, sources, sink);
    if (!p || sink.has_errors()) {
        throw error_from(sources, sink);
    }
    return std::move(*p);
}

struct PyIpcValidation {
    bool valid = false;
    bool goal_reached = false;
    std::optional<std::size_t> failed_step;
    std::string reason;
    plan::Plan plan;
    std::optional<PyState> final_state;
};

PyIpcValidation validate_ipc(const PyPddl& t, const py::handle& plan) {
    if (t.im->problem == nullptr) {
        throw py::value_error("the PDDL domain was imported without a problem");
    }
    auto steps = ipc_plan_arg(plan);
    pddl::IpcValidation v;
    {
        py::gil_scoped_release release;
        v = pddl::validate_ipc_plan(*t.im, steps);
    }
    PyIpcValidation out{v.valid, v.goal_reached, v.failed_step, v.reason, std::move(v.plan), {}};
    if (v.final_state) {
        out.final_state = PyState::owned(std::move(*v.final_state));
    }
    return out;
}

std::string to_ipc(const PyPddl& t, const py::handle& plan) {
    auto p = plan_arg(plan);
    if (t.im->problem != nullptr) { // steps of actions (catplan.plan's) as the rules carrying them
        p = plan::rule_plan(*t.im->domain, *t.im->problem->initial, p);
    }
    return pddl::write_ipc_plan(value_or_raise(pddl::to_ipc_plan(*t.im, p)));
}

} // namespace

pddl::IpcPlan ipc_plan_arg(const py::handle& plan) {
    if (py::isinstance<py::str>(plan)) {
        return ipc_plan(plan.cast<std::string>(), "<ipc plan>");
    }
    pddl::IpcPlan out;
    for (auto s : plan) {
        auto t = s.cast<py::tuple>();
        if (t.size() != 2) {
            throw py::type_error("an IPC step is a tuple (action, [args])");
        }
        pddl::IpcStep step;
        step.action = t[0].cast<std::string>();
        step.args = t[1].cast<std::vector<std::string>>();
        out.push_back(std::move(step));
    }
    return out;
}

py::list ipc_tuples(const pddl::IpcPlan& p) {
    py::list out;
    for (const auto& s : p) {
        out.append(py::make_tuple(s.action, s.args));
    }
    return out;
}

void bind_io(py::module_& m) {
    py::class_<PyPddl>(m, "PddlTask", R"doc(
A PDDL domain (and problem) imported as a catplan domain and problem: each type an object,
each predicate an object with one hom per argument, each action one or more DPO rules (its
variants: stack, stack~2, ...), so that plans of IPC planners can be validated, transferred
and written back.)doc")
        .def_property_readonly("domain", [](const PyPddl& t) { return PyDomain{t.im->domain}; })
        .def_property_readonly("problem",
                               [](const PyPddl& t) -> std::optional<PyProblem> {
                                   if (t.im->problem == nullptr) {
                                       return std::nullopt;
                                   }
                                   return PyProblem{t.im->problem};
                               })
        .def_property_readonly("schema",
                               [](const PyPddl& t) { return PySchema{t.im->domain->schema}; })
        .def_readonly("warnings", &PyPddl::warnings,
                      "Warnings met while reading the PDDL (Diagnostic): a requirement catplan "
                      "reads only as far as the domain uses what it supports.")
        .def_property_readonly(
            "actions",
            [](const PyPddl& t) {
                py::list out;
                for (const auto& a : t.im->actions) {
                    std::vector<std::string> rules;
                    for (const auto& v : a.variants) {
                        rules.push_back(v.rule->name);
                    }
                    out.append(py::make_tuple(a.action, rules));
                }
                return out;
            },
            "Each PDDL action with the names of its rule variants.")
        .def("validate", &validate_ipc, py::arg("plan"),
             "Replays an IPC plan (its text, or a list of (action, [args]) tuples) with PDDL's "
             "meaning; the reason of an invalid plan names the false precondition.")
        .def("to_ipc", &to_ipc, py::arg("plan"),
             "A plan on the imported domain (such as catplan.plan finds) as IPC plan text.")
        .def("__repr__", [](const PyPddl& t) {
            return "<PddlTask " + t.im->pddl_domain.name +
                   (t.im->pddl_problem ? " / " + t.im->pddl_problem->name : std::string()) + ">";
        });

    py::class_<PyIpcValidation>(m, "IpcValidation", "The outcome of replaying an IPC plan.")
        .def_readonly("valid", &PyIpcValidation::valid)
        .def_readonly("goal_reached", &PyIpcValidation::goal_reached)
        .def_readonly("failed_step", &PyIpcValidation::failed_step)
        .def_readonly("reason", &PyIpcValidation::reason)
        .def_readonly("plan", &PyIpcValidation::plan, "The rule variant applied at each step.")
        .def_readonly("final_state", &PyIpcValidation::final_state)
        .def("__bool__", [](const PyIpcValidation& v) { return v.valid; })
        .def("__repr__", [](const PyIpcValidation& v) {
            return v.valid ? std::string("<IpcValidation valid>")
                           : "<IpcValidation invalid: " + v.reason + ">";
        });

    m.def("load_pddl", &load_pddl, py::arg("domain"), py::arg("problem") = py::none(),
          "Reads a PDDL domain file (and problem file) into a PddlTask; raises CatplanError "
          "with located diagnostics.");
    m.def("loads_pddl", &loads_pddl, py::arg("domain"), py::arg("problem") = py::none(),
          "Like load_pddl, for PDDL text in memory.");
    m.def(
        "parse_ipc_plan",
        [](const std::string& text, const std::string& filename) {
            return ipc_tuples(ipc_plan(text, filename));
        },
        py::arg("text"), py::arg("filename") = "<ipc plan>",
        "Reads an IPC plan ('(unstack e d)' per line) into (action, [args]) tuples.");
    m.def(
        "export_pddl",
        [](const PyDomain& d) { return value_or_raise(pddl::export_domain(*d.ptr)); },
        py::arg("domain"),
        "The domain as a PDDL domain file; raises CatplanError when PDDL cannot express it.");
    m.def(
        "export_pddl_problem",
        [](const PyProblem& p) { return value_or_raise(pddl::export_problem(*p.ptr)); },
        py::arg("problem"),
        "The problem as a PDDL problem file. A goal that is a pattern is reached by the action "
        "reach-goal, which only the domain exported with its problem has (catplan pddl export "
        "--problem).");
}

} // namespace catplan::python
