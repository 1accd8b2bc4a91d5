// Plan transfer along an ontology map (the paper's Algorithm 1): catplan.transfer, the Transfer
// result with its steps, goal satisfaction and timings, replanning, and the HTML report.

#include "catplan/base/process.hpp"
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
    std::optional<std::int64_t> cost;
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
                    rp.edit_distance,
                    rp.cost};
}

/// A goal for the map's target schema (ValueError for a state on another one).
std::shared_ptr<const acset::ACSet> intended_goal(const PyMap& map, PyState& goal) {
    if (goal.get().schema_ptr() != map.ptr->target()) {
        throw py::value_error("the intended goal is on " + goal.get().schema().name() +
                              ", not on the map's target schema " + map.ptr->target()->name());
    }
    return goal.share();
}

PyTransfer run_transfer(const PyMap& map, const PyProblem& problem, const py::handle& plan_obj,
                        const transfer::TransferOptions& o, bool replan, const SearchArgs& search) {
    if (map.ptr->source() != problem.ptr->domain->schema) {
        throw py::value_error("map " + map.name + " goes from " + map.ptr->target()->name() +
                              " to " + map.ptr->source()->name() + ", but problem " +
                              problem.ptr->name + " is on " + problem.ptr->domain->schema->name());
    }
    PyTransfer r{nullptr, nullptr, map, problem, plan_arg(plan_obj), 0};
    Interruptible inter;
    auto options = search_options(search, inter);
    auto t = std::make_shared<transfer::TransferResult>(
        transfer::transfer_plan(*map.ptr, *problem.ptr, r.plan, o));
    r.transfer_peak_kib = catplan::peak_rss_kib();
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

/// The verdict of a transfer, kept alive by the result it belongs to.
struct VerdictRef {
    std::shared_ptr<const transfer::TransferResult> t;

    const transfer::Verdict& get() const { return t->verdict; }
};

std::string_view fault_kind(transfer::Fault::Kind k) {
    using K = transfer::Fault::Kind;
    switch (k) {
    case K::SourcePlan:
        return "source_plan";
    case K::Step:
        return "step";
    case K::Goal:
        return "goal";
    case K::IntendedGoal:
        return "intended_goal";
    case K::Divergence:
        return "divergence";
    }
    return "step";
}

std::string_view claim_kind(transfer::Claim::Kind k) {
    switch (k) {
    case transfer::Claim::Kind::ValidByConstruction:
        return "valid_by_construction";
    }
    return "valid_by_construction";
}

const transfer::Claim& claim_named(const transfer::Verdict& v, const std::string& kind) {
    for (const auto& c : v.claims) {
        if (claim_kind(c.kind) == kind) {
            return c;
        }
    }
    throw py::key_error("no claim '" + kind + "' (the claims: valid_by_construction)");
}

void bind_verdict(py::module_& m) {
    py::class_<transfer::Fault>(m, "Fault", R"doc(
One thing that makes a transfer invalid. kind is 'source_plan' (the source plan is invalid on
its problem), 'step' (a source step applies but its migration does not), 'goal' (Δ_F(G) does
not embed monically in the last target state), 'intended_goal' (the goal intended in the
target domain is not fully satisfied) or 'divergence' (with strict: after a step the target
state is not Δ_F of the source state).)doc")
        .def_property_readonly(
            "kind", [](const transfer::Fault& f) { return std::string(fault_kind(f.kind)); })
        .def_readonly("step", &transfer::Fault::step, "The step (0-based) it is about, or None.")
        .def_readonly("where", &transfer::Fault::where, "'step 3 pickup(B)', or ''.")
        .def_readonly("why", &transfer::Fault::why, "What is wrong, without the step.")
        .def("__str__", &transfer::Fault::to_string)
        .def("__repr__", [](const transfer::Fault& f) { return "<Fault " + f.to_string() + ">"; });

    py::class_<transfer::Hypothesis>(m, "Hypothesis",
                                     "A hypothesis of a theorem, and whether it "
                                     "holds for this transfer.")
        .def_readonly("statement", &transfer::Hypothesis::statement)
        .def_readonly("holds", &transfer::Hypothesis::holds);

    py::class_<transfer::Claim>(m, "Claim", R"doc(
A guarantee a transfer can give, claimed only when every hypothesis of its theorem holds.
'valid_by_construction': every migrated step applies and Y_i = Δ_F(X_i) without search (the
paper's Appendix A).)doc")
        .def_property_readonly(
            "kind", [](const transfer::Claim& c) { return std::string(claim_kind(c.kind)); })
        .def_readonly("hypotheses", &transfer::Claim::hypotheses)
        .def_property_readonly("holds", &transfer::Claim::holds)
        .def_property_readonly(
            "failing",
            [](const transfer::Claim& c) -> std::optional<transfer::Hypothesis> {
                const auto* h = c.failing();
                return h == nullptr ? std::nullopt : std::optional<transfer::Hypothesis>(*h);
            },
            "The first hypothesis that does not hold, or None.");

    py::class_<VerdictRef>(m, "Verdict", R"doc(
A transfer's verdict: valid or not, every fault in the order the transfer met them (the first
is the reason), the goal it is judged by (the intended goal when one was given, else Δ_F(G))
with the paper's Metric 1, and the claims with their hypotheses.)doc")
        .def_property_readonly("valid", [](const VerdictRef& v) { return v.get().valid(); })
        .def_property_readonly(
            "status", [](const VerdictRef& v) { return v.get().valid() ? "valid" : "invalid"; })
        .def_property_readonly(
            "reason", [](const VerdictRef& v) { return v.get().reason(); },
            "Why the transfer is invalid, in one sentence ('' when valid).")
        .def_property_readonly("faults", [](const VerdictRef& v) { return v.get().faults; })
        .def_property_readonly("goal", [](const VerdictRef& v) { return v.get().goal; })
        .def_property_readonly(
            "goal_name", [](const VerdictRef& v) { return v.get().goal_name; },
            "The intended goal's name ('' when judged by Δ_F(G)).")
        .def_property_readonly("claims", [](const VerdictRef& v) { return v.get().claims; })
        .def_property_readonly(
            "failed_step",
            [](const VerdictRef& v) -> std::optional<transfer::Fault> {
                const auto* f = v.get().failed_step();
                return f == nullptr ? std::nullopt : std::optional<transfer::Fault>(*f);
            },
            "The fault at the step the replay stopped at (source or target), or None.")
        .def_property_readonly("source_valid",
                               [](const VerdictRef& v) { return v.get().source_valid(); })
        .def(
            "claim",
            [](const VerdictRef& v, const std::string& kind) { return claim_named(v.get(), kind); },
            py::arg("kind"), "The claim of a kind ('valid_by_construction').")
        .def("__bool__", [](const VerdictRef& v) { return v.get().valid(); })
        .def("__repr__", [](const VerdictRef& v) {
            return v.get().valid() ? std::string("<Verdict valid>")
                                   : "<Verdict invalid: " + v.get().reason() + ">";
        });
}

void bind_results(py::module_& m) {
    bind_verdict(m);
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
                      "Levenshtein distance between the transferred and the replanned steps.")
        .def_readonly("cost", &PyReplan::cost,
                      "The replanned plan's cost where the problem's rules say costs (else None).");
}

// A plan's cost where the source problem sums costs and the plan has one.
std::optional<std::int64_t> cost_of(const PyTransfer& r, bool source) {
    auto costs = transfer::plan_costs(*r.t, *r.problem.ptr, r.plan);
    if (!costs) {
        return std::nullopt;
    }
    const auto& c = source ? costs->source : costs->target;
    return c ? std::optional(*c) : std::nullopt;
}

void bind_transfer_result(py::module_& m) {
    py::class_<PyTransfer>(m, "Transfer", "The outcome of a plan transfer along an ontology map.")
        .def_property_readonly("steps", &steps)
        .def_property_readonly(
            "verdict", [](const PyTransfer& r) { return VerdictRef{r.t}; },
            "Valid or not and why, every fault, the goal judged by, the claims.")
        .def_property_readonly(
            "valid", [](const PyTransfer& r) { return r.t->verdict.valid(); },
            "verdict.valid: every step transferred and the goal met.")
        .def_property_readonly(
            "reason", [](const PyTransfer& r) { return r.t->verdict.reason(); },
            "verdict.reason: why the transfer is invalid ('' when valid).")
        .def_property_readonly(
            "goal", [](const PyTransfer& r) { return r.t->verdict.goal; },
            "verdict.goal: goal satisfaction on the last target state reached.")
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
            "source_cost", [](const PyTransfer& r) { return cost_of(r, true); },
            "The source plan's cost where the problem's rules say costs (else None).")
        .def_property_readonly(
            "target_cost", [](const PyTransfer& r) { return cost_of(r, false); },
            "The target plan's cost in the generated actions, which read the source problem's "
            "function values carried by name (None without costs or where a value is missing).")
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
        .def("__bool__", [](const PyTransfer& r) { return r.t->verdict.valid(); })
        .def("__repr__", [](const PyTransfer& r) {
            return "<Transfer " + r.map.name + ": " + std::to_string(r.t->steps.size()) +
                   " steps, " +
                   (r.t->verdict.valid() ? std::string("valid")
                                         : "invalid: " + r.t->verdict.reason()) +
                   ">";
        });

    m.def(
        "transfer",
        [](const PyMap& map, const PyProblem& problem, const py::handle& plan, PyState* goal,
           const std::string& goal_name, bool rename_by_type, bool keep_states, bool replan,
           std::string search, std::string heuristic, std::uint64_t max_nodes, double max_time) {
            transfer::TransferOptions o;
            o.keep_states = keep_states;
            o.rename_by_type = rename_by_type;
            if (goal != nullptr) {
                o.goal = intended_goal(map, *goal);
                o.goal_name = goal_name.empty() ? goal->name() : goal_name;
            }
            SearchArgs s{
                std::move(search), std::move(heuristic), max_nodes, max_time, 0, py::none(), 1.0};
            return run_transfer(map, problem, plan, o, replan, s);
        },
        py::arg("map"), py::arg("problem"), py::arg("plan"), py::kw_only(),
        py::arg("goal") = py::none(), py::arg("goal_name") = "", py::arg("rename_by_type") = false,
        py::arg("keep_states") = false, py::arg("replan") = false, py::arg("search") = "bfs",
        py::arg("heuristic") = "hff", py::arg("max_nodes") = 0, py::arg("max_time") = 60.0,
        R"doc(Transfers a plan of a problem on the map's source schema along the map (the
paper's Algorithm 1): every action and match is migrated and applied in the target domain, each
step checked, and the goal Δ_F(G) embedded monically. goal, a state on the map's target schema,
is the goal intended in the target domain: the verdict then also asks that it be satisfied, and
goal satisfaction is measured for it (goal_name names it in the verdict's words; default: the
state's name). An invalid transfer is an answer (Transfer.verdict), not an exception. replan also plans from scratch in the target domain (search, heuristic, limits as in
catplan.plan) and compares. Runs without the GIL; Ctrl-C interrupts the replanning.)doc");
}

} // namespace

void bind_transfer(py::module_& m) {
    bind_results(m);
    bind_transfer_result(m);
}

} // namespace catplan::python
