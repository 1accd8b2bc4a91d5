#pragma once
// `catplan transfer` with PDDL inputs: the map's file imports the source (and target) PDDL
// domains, `--problem` is a PDDL problem of the source domain and `--plan` an IPC plan (as Fast
// Downward writes it, `; cost` line and all). pddl_transfer/ does the work; this file reads the
// files the options name and words what was found: the target plan in IPC form (written with -o),
// catplan's PDDL validator on Δ_F(I), Δ_F(G) (written as PDDL with --problem-output) and the
// comparison with the user's target problem (--target-problem).

#include "catplan/cli/common.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/pddl_transfer/pddl_transfer.hpp"
#include "catplan/transfer/transfer.hpp"

#include <iosfwd>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace catplan::cli {

/// What a transfer with PDDL inputs reads besides the common inputs.
struct PddlTransfer {
    /// What every plan of the transfer shares.
    std::shared_ptr<const pddl_transfer::Setting> setting;
    /// The source plan as written.
    pddl::IpcPlan plan;
};

/// Whether a --problem argument names a PDDL file.
bool is_pddl_problem(const std::string& problem);

/// Loads a transfer's inputs but the plan when --problem is a PDDL file; nullopt with every error
/// printed.
std::optional<TransferInputs> load_pddl_transfer_inputs(Session& s, const lang::Module& m,
                                                        TransferInputs in, const TransferArgs& a,
                                                        std::ostream& err);

/// Loads the IPC plan at `path` into in (whose PDDL side load_pddl_transfer_inputs loaded); false
/// with every error printed.
bool load_ipc_plan(Session& s, TransferInputs& in, const std::string& path, std::ostream& err);

/// What finish_pddl_transfer found: the plans' costs, the comparison with --target-problem and
/// the PDDL validator's verdict, in words (`text`, lines) and for --format json (`json`, the
/// object under "pddl").
struct PddlChecks {
    std::string text;
    nlohmann::ordered_json json = nlohmann::ordered_json::object();
    /// The target plan in IPC form, where the check wrote it (pddl_transfer::Checks).
    std::optional<pddl::IpcPlan> target_plan;
};

/// The transferred steps in IPC form (those of checks.target_plan where it has them all), each
/// with the source step it comes from and whether it corresponds or was repaired.
std::string pddl_steps_text(const TransferInputs& in, const transfer::TransferResult& t,
                            const PddlChecks& checks);

/// After a transfer with PDDL inputs: the target plan in IPC form put in `plan_text`, what
/// catplan's PDDL validator and the comparison with --target-problem found put in `checks`, and
/// --problem-output's file added to `outputs`, for the caller to write all or none of; returns
/// kOk, or kNo when the check or the comparison fails.
int finish_pddl_transfer(const TransferInputs& in, const TransferArgs& a,
                         const transfer::TransferResult& t, std::string& plan_text,
                         PddlChecks& checks, std::vector<OutputText>& outputs);

} // namespace catplan::cli
