// Plans, plan validation and the planner: catplan.Step, Plan, validate, plan.

#include "catplan/plan/actions.hpp"
#include "catplan/plan/validate.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

plan::Plan parse(const std::string& text, const std::string& filename) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_buffer(filename, text);
    auto p = plan::parse_plan(file, sources, sink);
    if (!p || sink.has_errors()) {
        throw error_from(sources, sink);
    }
    return std::move(*p);
}

plan::Plan load_plan(const std::string& path) {
    SourceManager sources;
    DiagnosticSink sink(sources);
    auto file = sources.add_file(path);
    if (!file) {
        sink.error("cannot read '" + path + "'");
        throw error_from(sources, sink);
    }
    auto p = plan::parse_plan(*file, sources, sink);
    if (!p || sink.has_errors()) {
        throw error_from(sources, sink);
    }
    return std::move(*p);
}

plan::Step step_arg(const py::handle& s) {
    if (py::isinstance<plan::Step>(s)) {
        return s.cast<plan::Step>();
    }
    if (py::isinstance<py::str>(s)) {
        auto p = parse(s.cast<std::string>(), "<step>");
        if (p.steps.size() != 1) {
            throw py::value_error("'" + s.cast<std::string>() + "' is not one step");
        }
        return p.steps.front();
    }
    if (py::isinstance<py::tuple>(s) && py::len(s) == 2) {
        auto t = s.cast<py::tuple>();
        plan::Step out;
        out.action = t[0].cast<std::string>();
        out.args = t[1].cast<std::vector<std::string>>();
        return out;
    }
    throw py::type_error("a step is a Step, a str such as 'unstack(E, D)' or a tuple (action, "
                         "[args])");
}

/// What validate returns.
struct PyValidation {
    bool valid = false;
    bool goal_reached = false;
    std::optional<std::size_t> failed_step;
    std::string reason;
    std::optional<std::int64_t> cost;
    std::vector<PyMorphism> matches;
    std::vector<PyState> states;
    std::optional<PyState> final_state;
};

PyValidation validate(PyProblem& problem, const py::handle& plan_obj, bool keep_states) {
    auto plan = plan_arg(plan_obj);
    plan::Validation v;
    {
        py::gil_scoped_release release;
        // Steps of actions as the rules that carry them out (plan/actions.hpp).
        plan = plan::rule_plan(*problem.ptr->domain, *problem.ptr->initial, plan);
        plan::ValidateOptions o;
        o.keep_states = keep_states;
        v = plan::validate_plan(*problem.ptr, plan, o);
    }
    PyValidation out;
    out.valid = v.valid;
    out.goal_reached = v.goal_reached;
    out.failed_step = v.failed_step;
    out.reason = v.reason;
    out.cost = v.cost;
    for (auto& x : v.states) {
        out.states.push_back(PyState::owned(std::move(x)));
    }
    const auto& domain = *problem.ptr->domain;
    for (std::size_t i = 0; i < v.matches.size(); ++i) {
        std::shared_ptr<const acset::ACSet> dom, codom;
        for (const auto& r : domain.rules) {
            if (r->name == plan.steps[i].action) {
                dom = std::shared_ptr<const acset::ACSet>(r, &r->L);
                break;
            }
        }
        if (i < out.states.size()) {
            codom = out.states[i].share();
        }
        out.matches.push_back(PyMorphism{std::move(v.matches[i]), dom, codom});
    }
    if (v.final_state) {
        out.final_state = PyState::owned(std::move(*v.final_state));
    }
    return out;
}

/// What plan returns.
struct PySearchResult {
    std::string status;
    std::optional<plan::Plan> plan;
    py::dict stats;
};

PySearchResult find_plan(PyProblem& problem, const SearchArgs& args) {
    plan::SearchResult r;
    {
        Interruptible inter;
        auto o = search_options(args, inter);
        try {
            r = plan::find_plan(*problem.ptr, o);
            if (r.plan) {
                r.plan = plan::action_plan(*problem.ptr->domain, *r.plan);
            }
        } catch (const Interrupted&) {
        }
        inter.finish();
    }
    return PySearchResult{std::string(plan::to_string(r.status)), r.plan, stats_dict(r.stats)};
}

void bind_plans(py::module_& m) {
    py::class_<plan::Step>(m, "Step",
                           "One step of a plan: an action and the names of the parts "
                           "bound to its parameters.")
        .def(py::init([](std::string action, std::vector<std::string> args) {
                 plan::Step s;
                 s.action = std::move(action);
                 s.args = std::move(args);
                 return s;
             }),
             py::arg("action"), py::arg("args") = std::vector<std::string>{})
        .def_readonly("action", &plan::Step::action)
        .def_readonly("args", &plan::Step::args)
        .def("__str__", &plan::Step::to_string)
        .def("__repr__", [](const plan::Step& s) { return "<Step " + s.to_string() + ">"; })
        .def("__eq__", [](const plan::Step& a,
                          const plan::Step& b) { return a.action == b.action && a.args == b.args; })
        .def("__hash__", [](const plan::Step& s) { return py::hash(py::str(s.to_string())); });

    py::class_<plan::Plan>(m, "Plan", "A list of steps such as unstack(E, D).")
        .def(py::init([](const py::iterable& steps) {
                 plan::Plan p;
                 for (auto s : steps) {
                     p.steps.push_back(step_arg(s));
                 }
                 return p;
             }),
             py::arg("steps") = py::list(),
             "A plan from steps: Step objects, strings such as 'unstack(E, D)', or (action, "
             "[args]) tuples.")
        .def_static("parse", &parse, py::arg("text"), py::arg("filename") = "<plan>",
                    "Reads plan text (one step per line or ';'-separated, '#' comments); raises "
                    "CatplanError with located diagnostics.")
        .def_static("load", &load_plan, py::arg("path"), "Reads a plan file.")
        .def_readonly("steps", &plan::Plan::steps)
        .def("__len__", [](const plan::Plan& p) { return p.steps.size(); })
        .def("__getitem__",
             [](const plan::Plan& p, long long i) {
                 auto n = static_cast<long long>(p.steps.size());
                 if (i < 0) {
                     i += n;
                 }
                 if (i < 0 || i >= n) {
                     throw py::index_error("plan index out of range");
                 }
                 return p.steps[static_cast<std::size_t>(i)];
             })
        .def("__iter__", [](const plan::Plan& p) { return py::iter(py::cast(p.steps)); })
        .def("__eq__", [](const plan::Plan& a,
                          const plan::Plan& b) { return a.to_string() == b.to_string(); })
        .def("__str__", &plan::Plan::to_string)
        .def("__repr__", [](const plan::Plan& p) {
            std::string text;
            for (const auto& s : p.steps) {
                text += (text.empty() ? "" : "; ") + s.to_string();
            }
            return "<Plan " + text + ">";
        });
}

void bind_validate_and_search(py::module_& m) {
    py::class_<PyValidation>(m, "Validation", "The outcome of replaying a plan on a problem.")
        .def_readonly("valid", &PyValidation::valid, "Every step applied and the goal reached.")
        .def_readonly("goal_reached", &PyValidation::goal_reached)
        .def_readonly("failed_step", &PyValidation::failed_step,
                      "The index (0-based) of the step that failed, or None.")
        .def_readonly("reason", &PyValidation::reason,
                      "Why the plan is invalid: 'step 3 pickup(B): no match: ...' or 'goal not "
                      "reached: ...'; '' when valid.")
        .def_readonly("cost", &PyValidation::cost,
                      "The cost of the steps applied when the problem's rules say costs ("
                      "cost = length(from, to)), else None.")
        .def_readonly("matches", &PyValidation::matches,
                      "The match (Morphism Pre -> state) of each step applied.")
        .def_readonly("states", &PyValidation::states,
                      "With keep_states: the initial state and the state after each step.")
        .def_readonly("final_state", &PyValidation::final_state, "The last state reached.")
        .def("__bool__", [](const PyValidation& v) { return v.valid; })
        .def("__repr__", [](const PyValidation& v) {
            return v.valid ? std::string("<Validation valid>")
                           : "<Validation invalid: " + v.reason + ">";
        });
    m.def("validate", &validate, py::arg("problem"), py::arg("plan"), py::kw_only(),
          py::arg("keep_states") = false,
          R"doc(Replays a plan from the problem's initial state and checks that the goal embeds
monically in the last state. An invalid plan is an answer (Validation.valid is False, reason
says why), not an exception; a plan with a syntax error raises CatplanError.)doc");

    py::class_<PySearchResult>(m, "SearchResult", "The outcome of a plan search.")
        .def_readonly("status", &PySearchResult::status,
                      "'solved', 'unsolvable', 'node limit', 'time limit' or 'memory limit'.")
        .def_readonly("plan", &PySearchResult::plan, "The plan found, or None.")
        .def_readonly("stats", &PySearchResult::stats,
                      "expanded, evaluated, generated, duplicates, states, frontier, f, seconds, "
                      "setup_seconds, ground_seconds, search_seconds, variables, actions, plans, "
                      "memory, peak_memory (resident bytes of the process), initial_h (per "
                      "heuristic, its value on the initial state; None for a dead end).")
        .def_property_readonly("solved",
                               [](const PySearchResult& r) { return r.status == "solved"; })
        .def("__repr__", [](const PySearchResult& r) {
            return "<SearchResult " + r.status +
                   (r.plan ? ", " + std::to_string(r.plan->steps.size()) + " steps" : "") + ">";
        });
    m.def(
        "plan",
        [](PyProblem& problem, std::string search, std::string heuristic, std::uint64_t max_nodes,
           double max_time, double max_memory_mb, py::object progress, double progress_interval) {
            return find_plan(problem, SearchArgs{std::move(search), std::move(heuristic), max_nodes,
                                                 max_time, max_memory_mb, std::move(progress),
                                                 progress_interval});
        },
        py::arg("problem"), py::kw_only(), py::arg("search") = "bfs", py::arg("heuristic") = "hff",
        py::arg("max_nodes") = 0, py::arg("max_time") = 0.0, py::arg("max_memory_mb") = 0.0,
        py::arg("progress") = py::none(), py::arg("progress_interval") = 1.0,
        R"doc(Searches for a plan from the problem's initial state to a state the goal embeds in.

search: 'bfs' (shortest plans), 'astar' or 'gbfs'; heuristic (for astar and gbfs): 'blind',
'goalcount', 'hadd' or 'hff'. Limits (0 = none): expanded states, seconds, megabytes of stored
states. progress, when given, is called about every progress_interval seconds with a dict of
statistics; an exception it raises stops the search and propagates. Runs without the GIL;
Ctrl-C interrupts it (KeyboardInterrupt).)doc");
}

} // namespace

plan::Plan plan_arg(const py::handle& plan) {
    if (py::isinstance<plan::Plan>(plan)) {
        return plan.cast<plan::Plan>();
    }
    if (py::isinstance<py::str>(plan)) {
        return parse(plan.cast<std::string>(), "<plan>");
    }
    if (py::isinstance<py::iterable>(plan)) {
        plan::Plan p;
        for (auto s : plan) {
            p.steps.push_back(step_arg(s));
        }
        return p;
    }
    throw py::type_error("a plan is a Plan, plan text or a list of steps");
}

py::dict stats_dict(const plan::SearchStats& s) {
    py::dict d;
    d["expanded"] = s.expanded;
    d["evaluated"] = s.evaluated;
    d["generated"] = s.generated;
    d["duplicates"] = s.duplicates;
    d["states"] = s.states;
    d["frontier"] = s.frontier;
    d["f"] = s.f;
    d["seconds"] = s.seconds;
    d["setup_seconds"] = s.setup_seconds;
    d["ground_seconds"] = s.ground_seconds;
    d["search_seconds"] = s.search_seconds();
    d["variables"] = s.variables;
    d["actions"] = s.actions;
    d["plans"] = s.plans;
    d["memory"] = s.memory;
    d["peak_memory"] = s.peak_memory;
    py::dict initial;
    for (const auto& [kind, value] : s.initial_h) {
        initial[py::str(std::string(plan::to_string(kind)))] =
            value ? py::object(py::int_(*value)) : py::object(py::none());
    }
    d["initial_h"] = initial;
    return d;
}

plan::SearchOptions search_options(const SearchArgs& args, Interruptible& inter) {
    plan::SearchOptions o;
    auto kind = plan::parse_search(args.search);
    auto h = plan::parse_heuristic(args.heuristic);
    if (!kind) {
        throw py::value_error("search is 'bfs', 'astar' or 'gbfs', not '" + args.search + "'");
    }
    if (!h) {
        throw py::value_error("heuristic is 'blind', 'goalcount', 'hadd' or 'hff', not '" +
                              args.heuristic + "'");
    }
    o.search = *kind;
    o.heuristic = *h;
    o.max_nodes = args.max_nodes;
    o.max_seconds = args.max_time;
    o.max_bytes = static_cast<std::size_t>(args.max_memory_mb * 1024 * 1024);
    // Reports come often enough to answer Ctrl-C quickly; the Python callback is called at its
    // own interval.
    o.progress_interval = 0.05;
    auto next_call = std::make_shared<double>(args.progress_interval);
    // Captures by reference only: no Python object may be copied without the GIL.
    o.progress = [&inter, &args, next_call](const plan::SearchStats& stats) {
        bool stop = inter.check();
        if (!stop && args.progress && !args.progress.is_none() && stats.seconds >= *next_call) {
            *next_call = stats.seconds + args.progress_interval;
            stop = inter.with_gil([&] { args.progress(stats_dict(stats)); });
        }
        if (stop) {
            throw Interrupted{};
        }
    };
    return o;
}

void bind_plan(py::module_& m) {
    bind_plans(m);
    bind_validate_and_search(m);
}

} // namespace catplan::python
