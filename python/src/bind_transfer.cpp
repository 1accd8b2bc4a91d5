// Plan transfer along an ontology map (the paper's Algorithm 1): catplan.transfer, the Transfer
// result with its steps, goal satisfaction and timings, replanning, and the HTML report.

#include "catplan/report/report.hpp"
#include "catplan/transfer/transfer.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

/// One transferred step, with both matches.
struct PyTransferStep {
    plan::Step source, target;
    PyMorphism source_match, target_match;
    std::string source_bindings, target_bindings;
    std::vector<std::string> lost_parameters;
};

/// Replanning in the target domain (the paper's Metric 5).
struct PyReplan {
    std::string status;
    std::vector<plan::Step> steps;
    py::dict stats;
    double ms = 0;
    long peak_rss_kib = 0;
    std::size_t edit_distance = 0;
};

/// What transfer returns: the library's result and the inputs, for the report.
struct PyTransfer {
    std::shared_ptr<const transfer::TransferResult> t;
    std::shared_ptr<const transfer::Replan> replan;
    PyMap map;
    PyProblem problem;
    plan::Plan plan;
    long transfer_peak_kib = 0;
};

std::shared_ptr<const acset::ACSet> rule_pre(const plan::DomainPtr& d, const std::string& name) {
    if (d == nullptr) {
        return nullptr;
    }
    for (const auto& r : d->rules) {
        if (r->name == name) {
            return {r, &r->L};
        }
    }
    return nullptr;
}

std::shared_ptr<const acset::ACSet>
state_at(const std::shared_ptr<const transfer::TransferResult>& t,
         const std::vector<acset::ACSet>& states, std::size_t i) {
    return i < states.size() ? std::shared_ptr<const acset::ACSet>(t, &states[i]) : nullptr;
}

std::vector<PyTransferStep> steps(const PyTransfer& r) {
    const auto& t = r.t;
    std::vector<PyTransferStep> out;
    for (std::size_t i = 0; i < t->steps.size(); ++i) {
        const auto& s = t->steps[i];
        PyTransferStep p;
        p.source = s.source;
        p.target = s.target;
        p.source_match =
            PyMorphism{s.source_match, rule_pre(r.problem.ptr->domain, s.source.action),
                       state_at(t, t->source_states, i)};
        p.target_match =
            PyMorphism{s.target_match, rule_pre(t->target_domain.domain, s.target.action),
                       state_at(t, t->target_states, i)};
        p.source_bindings = s.source_bindings;
        p.target_bindings = s.target_bindings;
        p.lost_parameters = s.lost_parameters;
        out.push_back(std::move(p));
    }
    return out;
}

std::optional<PyState> state_or_none(const std::shared_ptr<const acset::ACSet>& x) {
    if (x == nullptr) {
        return std::nullopt;
    }
    return PyState(x);
}

std::vector<PyState> states(const std::shared_ptr<const transfer::TransferResult>& t,
                            const std::vector<acset::ACSet>& xs) {
    std::vector<PyState> out;
    for (const auto& x : xs) {
        out.emplace_back(std::shared_ptr<const acset::ACSet>(t, &x));
    }
    return out;
}

PyReplan replan_of(const transfer::Replan& rp) {
    return PyReplan{std::string(plan::to_string(rp.search.status)),
                    rp.steps,
                    stats_dict(rp.search.stats),
                    rp.ms,
                    rp.peak_rss_kib,
                    rp.edit_distance};
}

PyTransfer run_transfer(const PyMap& map, const PyProblem& problem, const py::handle& plan_obj,
                        bool rename_by_type, bool keep_states, bool replan,
                        const SearchArgs& search) {
    if (map.ptr->source() != problem.ptr->domain->schema) {
        throw py::value_error("map " + map.name + " goes from " + map.ptr->target()->name() +
                              " to " + map.ptr->source()->name() + ", but problem " +
                              problem.ptr->name + " is on " + problem.ptr->domain->schema->name());
    }
    PyTransfer r{nullptr, nullptr, map, problem, plan_arg(plan_obj), 0};
    Interruptible inter;
    auto options = search_options(search, inter);
    transfer::TransferOptions o;
    o.keep_states = keep_states;
    o.rename_by_type = rename_by_type;
    auto t = std::make_shared<transfer::TransferResult>(
        transfer::transfer_plan(*map.ptr, *problem.ptr, r.plan, o));
    r.transfer_peak_kib = transfer::peak_rss_kib();
    if (replan && t->target_domain.domain != nullptr && t->target_initial && t->target_goal) {
        try {
            r.replan = std::make_shared<const transfer::Replan>(transfer::replan(*t, options));
        } catch (const Interrupted&) {
        }
    }
    r.t = std::move(t);
    inter.finish();
    return r;
}

std::string report_html(const PyTransfer& r, bool no_timing) {
    report::ReportInput in;
    in.map = r.map.ptr.get();
    in.map_name = r.map.name;
    in.problem = r.problem.ptr.get();
    in.plan = &r.plan;
    in.transfer = r.t.get();
    in.replan = r.replan.get();
    in.transfer_peak_kib = r.transfer_peak_kib;
    in.no_timing = no_timing;
    py::gil_scoped_release release;
    return report::html_report(in);
}

void bind_results(py::module_& m) {
    py::class_<transfer::GoalSatisfaction>(m, "GoalSatisfaction", R"doc(
The paper's Metric 1: the largest fraction of the goal's statements (each part, hom value and
concrete attribute value) that one injective assignment satisfies, with the statements it
leaves unsatisfied, in words.)doc")
        .def_readonly("satisfied", &transfer::GoalSatisfaction::satisfied)
        .def_readonly("total", &transfer::GoalSatisfaction::total)
        .def_readonly("unsatisfied", &transfer::GoalSatisfaction::unsatisfied)
        .def_readonly("exact", &transfer::GoalSatisfaction::exact,
                      "False when the search was cut short (satisfied is then a lower bound).")
        .def_property_readonly("fraction", &transfer::GoalSatisfaction::fraction)
        .def("__repr__", [](const transfer::GoalSatisfaction& g) {
            return "<GoalSatisfaction " + std::to_string(g.satisfied) + "/" +
                   std::to_string(g.total) + ">";
        });

    py::class_<PyTransferStep>(m, "TransferStep", "One transferred step.")
        .def_readonly("source", &PyTransferStep::source, "The step as written in the source plan.")
        .def_readonly("target", &PyTransferStep::target,
                      "The migrated action with the target parts it binds.")
        .def_readonly("source_match", &PyTransferStep::source_match,
                      "Pre -> X_{i-1} (codom known with keep_states).")
        .def_readonly("target_match", &PyTransferStep::target_match,
                      "Δ_F(Pre) -> Y_{i-1} (codom known with keep_states).")
        .def_readonly("source_bindings", &PyTransferStep::source_bindings)
        .def_readonly("target_bindings", &PyTransferStep::target_bindings)
        .def_readonly("lost_parameters", &PyTransferStep::lost_parameters,
                      "Parameters of the source action that the map does not see.")
        .def_property_readonly("action", [](const PyTransferStep& s) { return s.target.action; })
        .def_property_readonly("arguments", [](const PyTransferStep& s) { return s.target.args; })
        .def("__repr__", [](const PyTransferStep& s) {
            return "<TransferStep " + s.source.to_string() + " -> " + s.target.to_string() + ">";
        });

    py::class_<PyReplan>(m, "Replan", "Replanning from scratch in the target domain.")
        .def_readonly("status", &PyReplan::status)
        .def_readonly("steps", &PyReplan::steps)
        .def_readonly("stats", &PyReplan::stats)
        .def_readonly("ms", &PyReplan::ms)
        .def_readonly("peak_rss_kib", &PyReplan::peak_rss_kib)
        .def_readonly("edit_distance", &PyReplan::edit_distance,
                      "Levenshtein distance between the transferred and the replanned steps.");
}

void bind_transfer_result(py::module_& m) {
    py::class_<PyTransfer>(m, "Transfer", "The outcome of a plan transfer along an ontology map.")
        .def_property_readonly("steps", &steps)
        .def_property_readonly(
            "valid", [](const PyTransfer& r) { return r.t->valid; },
            "Every step transferred and the goal reached.")
        .def_property_readonly(
            "reason", [](const PyTransfer& r) { return r.t->reason; },
            "Why the transfer is invalid ('' when valid).")
        .def_property_readonly("goal_reached",
                               [](const PyTransfer& r) { return r.t->goal_reached; })
        .def_property_readonly(
            "goal", [](const PyTransfer& r) { return r.t->goal; },
            "Goal satisfaction (GoalSatisfaction) on the last target state.")
        .def_property_readonly(
            "failed_step",
            [](const PyTransfer& r) -> py::object {
                if (!r.t->failed_step) {
                    return py::none();
                }
                return py::make_tuple(r.t->failed_step->index, r.t->failed_step->reason);
            },
            "(index, reason) of the step that could not be transferred, or None.")
        .def_property_readonly("source_valid",
                               [](const PyTransfer& r) { return r.t->source_valid; })
        .def_property_readonly("source_reason",
                               [](const PyTransfer& r) { return r.t->source_reason; })
        .def_property_readonly(
            "migration",
            [](const PyTransfer& r) { return std::string(transfer::to_string(r.t->migration)); },
            "'delta' or 'conjunctive'.")
        .def_property_readonly("target_plan",
                               [](const PyTransfer& r) {
                                   plan::Plan p;
                                   for (const auto& s : r.t->steps) {
                                       p.steps.push_back(s.target);
                                   }
                                   return p;
                               })
        .def_property_readonly(
            "target_domain",
            [](const PyTransfer& r) -> std::optional<PyDomain> {
                if (r.t->target_domain.domain == nullptr) {
                    return std::nullopt;
                }
                return PyDomain{r.t->target_domain.domain};
            },
            "The generated target domain (Δ_F of each source rule).")
        .def_property_readonly(
            "target_initial",
            [](const PyTransfer& r) { return state_or_none(r.t->target_initial); })
        .def_property_readonly("target_goal",
                               [](const PyTransfer& r) { return state_or_none(r.t->target_goal); })
        .def_property_readonly("final_state",
                               [](const PyTransfer& r) -> std::optional<PyState> {
                                   if (!r.t->final_state) {
                                       return std::nullopt;
                                   }
                                   return PyState({r.t, &*r.t->final_state});
                               })
        .def_property_readonly("source_states",
                               [](const PyTransfer& r) { return states(r.t, r.t->source_states); })
        .def_property_readonly("target_states",
                               [](const PyTransfer& r) { return states(r.t, r.t->target_states); })
        .def_property_readonly(
            "timings",
            [](const PyTransfer& r) {
                py::dict d;
                d["migrate_ms"] = r.t->timings.migrate_ms;
                d["apply_ms"] = r.t->timings.apply_ms;
                d["validate_ms"] = r.t->timings.validate_ms;
                d["total_ms"] = r.t->timings.total_ms;
                return d;
            },
            "Wall-clock milliseconds: migrate_ms, apply_ms, validate_ms, total_ms.")
        .def_property_readonly("replan",
                               [](const PyTransfer& r) -> std::optional<PyReplan> {
                                   if (!r.replan) {
                                       return std::nullopt;
                                   }
                                   return replan_of(*r.replan);
                               })
        .def("report", &report_html, py::kw_only(), py::arg("no_timing") = false,
             "The HTML report of the transfer: one self-contained page (pictures of the states "
             "need keep_states=True).")
        .def("__bool__", [](const PyTransfer& r) { return r.t->valid; })
        .def("__repr__", [](const PyTransfer& r) {
            return "<Transfer " + r.map.name + ": " + std::to_string(r.t->steps.size()) +
                   " steps, " + (r.t->valid ? std::string("valid") : "invalid: " + r.t->reason) +
                   ">";
        });

    m.def(
        "transfer",
        [](const PyMap& map, const PyProblem& problem, const py::handle& plan, bool rename_by_type,
           bool keep_states, bool replan, std::string search, std::string heuristic,
           std::uint64_t max_nodes, double max_time) {
            SearchArgs s{
                std::move(search), std::move(heuristic), max_nodes, max_time, 0, py::none(), 1.0};
            return run_transfer(map, problem, plan, rename_by_type, keep_states, replan, s);
        },
        py::arg("map"), py::arg("problem"), py::arg("plan"), py::kw_only(),
        py::arg("rename_by_type") = false, py::arg("keep_states") = false,
        py::arg("replan") = false, py::arg("search") = "bfs", py::arg("heuristic") = "hff",
        py::arg("max_nodes") = 0, py::arg("max_time") = 60.0,
        R"doc(Transfers a plan of a problem on the map's source schema along the map (the
paper's Algorithm 1): every action and match is migrated and applied in the target domain, each
step checked, and the goal Δ_F(G) embedded monically. An invalid transfer is an answer, not an
exception. replan also plans from scratch in the target domain (search, heuristic, limits as in
catplan.plan) and compares. Runs without the GIL; Ctrl-C interrupts the replanning.)doc");
}

} // namespace

void bind_transfer(py::module_& m) {
    bind_results(m);
    bind_transfer_result(m);
}

} // namespace catplan::python
