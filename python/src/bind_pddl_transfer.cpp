// A plan transfer with PDDL inputs, as `catplan transfer MAP.cp --problem P.pddl --plan sas_plan`
// does it: catplan.transfer_pddl and its result, catplan.PddlTransfer.

#include "catplan/base/process.hpp"
#include "catplan/pddl/steps.hpp"
#include "catplan/pddl_transfer/pddl_transfer.hpp"

#include "common.hpp"

namespace catplan::python {

namespace {

/// One source step and what it became in the target.
struct PyPddlStep {
    py::tuple source;
    std::string kind; // "corresponds", "repaired" or "generated"
    py::list target;  // the target steps, (action, [args]) each
    std::optional<std::string> action;
    std::optional<std::size_t> repair_reused_from;
    bool repair_from_action = false;
    std::size_t expanded = 0;
    std::optional<std::int64_t> repair_cost;
    bool repair_least_cost = false;
};

/// What transfer_pddl returns.
struct PyPddlTransfer {
    PyTransfer transfer;
    std::shared_ptr<const pddl_transfer::Setting> setting;
    pddl::IpcPlan plan;
    pddl_transfer::Checks checks;
};

/// The module's sources, copied with the same file ids: a transfer's problem and plan are read
/// into the copy, so that the module is not changed (it may be used from other threads) and does
/// not grow with each call, while diagnostics in the imported domains still render.
SourceManager copy_of(const SourceManager& s) {
    SourceManager out;
    for (std::uint32_t i = 0; i < s.num_files(); ++i) {
        out.add_buffer(std::string(s.name(i)), std::string(s.text(i)));
    }
    return out;
}

/// A file read into sources (the path as given); CatplanError when it cannot be read.
std::uint32_t add_file(SourceManager& sources, const std::string& path) {
    auto f = sources.add_file(path);
    if (!f) {
        throw error_from("cannot read '" + path + "'");
    }
    return *f;
}

/// A path given as str or os.PathLike.
std::string path_arg(const py::handle& p) {
    return py::module_::import("os").attr("fspath")(p).cast<std::string>();
}

PyPddlTransfer transfer_pddl(const PyModule& m, const std::string& map, const py::handle& problem,
                             const py::handle& plan_obj, const py::handle& target_problem,
                             bool keep_states) {
    const lang::Declaration* d = m.module.find(map);
    if (d == nullptr || d->kind != lang::DeclKind::Map) {
        throw py::key_error("no map named '" + map + "' in the module");
    }
    SourceManager sources = copy_of(*m.sources);
    DiagnosticSink sink(sources);
    std::uint32_t problem_file = add_file(sources, path_arg(problem));
    std::optional<std::uint32_t> target_file;
    if (!target_problem.is_none()) {
        target_file = add_file(sources, path_arg(target_problem));
    }
    // The plan is read from text, so that its errors point into it.
    std::string text = py::isinstance<py::str>(plan_obj)
                           ? plan_obj.cast<std::string>()
                           : pddl::write_ipc_plan(ipc_plan_arg(plan_obj));
    std::uint32_t plan_file = sources.add_buffer("<ipc plan>", text);
    PyPddlTransfer r;
    {
        py::gil_scoped_release release;
        auto setting =
            pddl_transfer::load_setting(m.module, *d, problem_file, target_file, sources, sink);
        std::optional<pddl::IpcPlan> plan;
        if (setting) {
            plan = pddl_transfer::read_plan(*setting, plan_file, sources, sink);
        }
        if (!setting || !plan) {
            throw error_from(sources, sink);
        }
        r.setting = std::make_shared<const pddl_transfer::Setting>(std::move(*setting));
        r.plan = std::move(*plan);
        auto options = pddl_transfer::transfer_options(*r.setting, r.plan);
        options.keep_states = keep_states;
        r.transfer = PyTransfer{nullptr,
                                nullptr,
                                PyMap{r.setting->map, map},
                                PyProblem{r.setting->source->problem},
                                pddl_transfer::source_plan(*r.setting, r.plan),
                                0};
        auto t = std::make_shared<transfer::TransferResult>(transfer::transfer_plan(
            *r.setting->map, *r.setting->source->problem, r.transfer.plan, options));
        r.transfer.transfer_peak_kib = catplan::peak_rss_kib();
        r.checks = pddl_transfer::check(*r.setting, r.plan, *t);
        r.transfer.t = std::move(t);
    }
    return r;
}

py::tuple ipc_tuple(const pddl::IpcStep& s) {
    return py::make_tuple(s.action, s.args);
}

std::vector<PyPddlStep> pddl_steps(const PyPddlTransfer& r) {
    const auto& st = *r.setting;
    std::vector<PyPddlStep> out;
    for (std::size_t i = 0; i < r.transfer.t->steps.size(); ++i) {
        const auto& s = r.transfer.t->steps[i];
        PyPddlStep p;
        p.source = ipc_tuple(r.plan[i]);
        p.kind = std::string(transfer::to_string(s.kind));
        for (const auto& step : s.target_steps) {
            auto ipc = pddl_transfer::ipc_step(st, step);
            p.target.append(ipc ? ipc_tuple(*ipc) : py::make_tuple(step.action, step.args));
        }
        if (s.kind == transfer::StepTransfer::Kind::Corresponds) {
            p.action = st.actions->name_of(s.target.action);
        }
        p.repair_reused_from = s.repair_reused_from;
        p.repair_from_action = s.repair_from_action;
        p.expanded = s.repair_stats.expanded;
        p.repair_cost = s.repair_cost;
        p.repair_least_cost = s.repair_least_cost;
        out.push_back(std::move(p));
    }
    return out;
}

/// The transfer is valid and the PDDL side's checks pass.
bool all_valid(const PyPddlTransfer& r) {
    return r.transfer.t->verdict.valid() && r.checks.ok(*r.transfer.t);
}

std::optional<std::int64_t> cost_total(const std::optional<pddl::PlanCost>& c) {
    if (!c || !c->undefined.empty()) {
        return std::nullopt;
    }
    return c->total;
}

py::object comparison(const PyPddlTransfer& r) {
    const auto& c = r.checks.comparison;
    if (!c) {
        return py::none();
    }
    py::dict d;
    d["name"] = c->name;
    d["same"] = c->same();
    d["only_in_migrated"] = c->only_in_migrated;
    d["only_in_target_problem"] = c->only_in_target_problem;
    return d;
}

void bind_step(py::module_& m) {
    py::class_<PyPddlStep>(m, "PddlTransferStep", "One source step and the target steps it became.")
        .def_readonly("source", &PyPddlStep::source, "The source step, (action, [args]).")
        .def_readonly("kind", &PyPddlStep::kind,
                      "'corresponds' (one target action is Δ_F of the source action), 'repaired' "
                      "(planned locally with the target's actions; maybe several steps or none) "
                      "or 'generated' (the migrated action: the target is not a PDDL domain).")
        .def_readonly("target", &PyPddlStep::target, "The target steps, (action, [args]) each.")
        .def_readonly("action", &PyPddlStep::action,
                      "The target action that corresponds (None unless kind is 'corresponds').")
        .def_readonly("repair_reused_from", &PyPddlStep::repair_reused_from,
                      "The earlier step (0-based) whose repair was renamed for this one, or None.")
        .def_readonly("repair_from_action", &PyPddlStep::repair_from_action,
                      "Whether the repair was found by a search from the migrated action's own "
                      "sides (its left side to its right side), no other part of the state.")
        .def_readonly("expanded", &PyPddlStep::expanded,
                      "States the repair's search expanded (0 when none ran).")
        .def_readonly("repair_cost", &PyPddlStep::repair_cost,
                      "What the repair's steps cost where the target's costs are known, or None.")
        .def_readonly("repair_least_cost", &PyPddlStep::repair_least_cost,
                      "Whether no plan of the focus (or state) the repair searched costs less: "
                      "its search summed the target's costs with A* and LM-cut.")
        .def("__repr__", [](const PyPddlStep& s) {
            std::string source = py::repr(s.source);
            return "<PddlTransferStep " + source + " " + s.kind + ": " +
                   std::to_string(py::len(s.target)) + " target steps>";
        });
}

} // namespace

void bind_pddl_transfer(py::module_& m) {
    bind_step(m);
    py::class_<PyPddlTransfer>(m, "PddlTransfer", R"doc(
A transfer with PDDL inputs: the Transfer, the target plan in the target domain's own actions
in IPC form, and what catplan's PDDL validator and the comparison with the user's target
problem found.)doc")
        .def_property_readonly(
            "transfer", [](const PyPddlTransfer& r) { return r.transfer; },
            "The Transfer: verdict, steps with their matches, states with keep_states.")
        .def_property_readonly(
            "valid", &all_valid,
            "The transfer is valid, the PDDL validator accepts the target plan and the target "
            "problem, when given, starts in Δ_F(I).")
        .def_property_readonly("steps", &pddl_steps, "Per source step, what it became.")
        .def_property_readonly(
            "target_plan",
            [](const PyPddlTransfer& r) -> py::object {
                if (!r.checks.target_plan) {
                    return py::none();
                }
                return ipc_tuples(*r.checks.target_plan);
            },
            "The target plan, (action, [args]) per step (None when the target is not a PDDL "
            "domain or no target state was reached).")
        .def_property_readonly(
            "plan_text", [](const PyPddlTransfer& r) { return r.checks.plan_text; },
            "The target plan as an IPC plan file holds it, with its '; cost' line.")
        .def_property_readonly(
            "problem_text",
            [](const PyPddlTransfer& r) -> std::optional<std::string> {
                if (!r.checks.migrated) {
                    return std::nullopt;
                }
                return pddl::write_problem(*r.checks.migrated);
            },
            "Δ_F(I) and Δ_F(G) as a PDDL problem of the target domain (as --problem-output "
            "writes it).")
        .def_property_readonly(
            "source_cost", [](const PyPddlTransfer& r) { return cost_total(r.checks.source_cost); },
            "The source plan's cost when the source actions have costs (else None).")
        .def_property_readonly(
            "target_cost", [](const PyPddlTransfer& r) { return cost_total(r.checks.target_cost); },
            "The target plan's cost when the target actions have costs and their values are "
            "known (else None).")
        .def_property_readonly(
            "uncarried_values", [](const PyPddlTransfer& r) { return r.setting->uncarried_values; },
            "Source values the map's functions section names that Δ_F(I) could not take, as "
            "'(road-length a t1)'.")
        .def_property_readonly(
            "pddl_valid",
            [](const PyPddlTransfer& r) -> std::optional<bool> {
                if (!r.checks.validation) {
                    return std::nullopt;
                }
                return r.checks.validation->valid;
            },
            "catplan's PDDL validator on the target plan, Δ_F(I) and Δ_F(G) (None when it did "
            "not run).")
        .def_property_readonly(
            "pddl_reason",
            [](const PyPddlTransfer& r) {
                return r.checks.validation ? r.checks.validation->reason : std::string();
            },
            "Why the PDDL validator rejects the target plan ('' when it accepts it).")
        .def_property_readonly(
            "unwritten_goal_conditions",
            [](const PyPddlTransfer& r) { return r.checks.unwritten_goal_conditions; },
            "Conditions of Δ_F(G) that a PDDL goal cannot say, left out of the PDDL check.")
        .def_property_readonly("comparison", &comparison,
                               "With target_problem: a dict with name, same, only_in_migrated "
                               "and only_in_target_problem (else None).")
        .def("__bool__", &all_valid)
        .def("__repr__", [](const PyPddlTransfer& r) {
            return "<PddlTransfer " + r.transfer.map.name + ": " +
                   std::to_string(r.transfer.t->steps.size()) + " source steps, " +
                   (r.checks.target_plan ? std::to_string(r.checks.target_plan->size())
                                         : std::string("no")) +
                   " target steps>";
        });

    m.def("transfer_pddl", &transfer_pddl, py::arg("module"), py::arg("map"), py::arg("problem"),
          py::arg("plan"), py::kw_only(), py::arg("target_problem") = py::none(),
          py::arg("keep_states") = false,
          R"doc(Transfers a plan of a PDDL problem along the module's map, as `catplan transfer
MAP.cp --map MAP --problem P.pddl --plan sas_plan` does: the module's file imports the source
(and target) PDDL domains, problem is the path (str or os.PathLike) of a PDDL problem of the source domain, plan an
IPC plan (its text, as Fast Downward writes it, '; cost' line and all, or a list of (action,
[args])). Each source step becomes the target action that is Δ_F of its action, or is repaired
with the target's own actions. target_problem, the path of the user's own target problem, is
compared with Δ_F(I), and its goal is the one the verdict judges. CatplanError on bad input;
an invalid transfer is an answer (PddlTransfer.valid). Runs without the GIL.)doc");
}

} // namespace catplan::python
