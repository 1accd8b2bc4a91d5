#pragma once
// `catplan transfer` with PDDL inputs: the map's file imports the source (and target) PDDL
// domains, `--problem` is a PDDL problem of the source domain and `--plan` an IPC plan (as Fast
// Downward writes it, `; cost` line and all). The target plan is carried out in the target
// domain's own actions where it is a PDDL domain (transfer/correspond.hpp, repair.hpp), printed in
// IPC form, written as an IPC plan with -o, and checked by catplan's PDDL validator on the target
// problem Δ_F(I), Δ_F(G) (written as PDDL with --problem-output, or compared with the user's
// target problem given by --target-problem).

#include "catplan/cli/common.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
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
    /// The source domain's import with the problem (its rules may be the problem's own).
    std::shared_ptr<const pddl::Import> source;
    /// The target domain's import, when the map's target is a PDDL domain (else null).
    std::shared_ptr<const pddl::Import> target;
    /// The target's own actions, matched to the generated ones (with the target).
    std::shared_ptr<const transfer::TargetActions> actions;
    /// The source plan as written.
    pddl::IpcPlan plan;
    /// --target-problem: the user's own target problem.
    std::optional<pddl::Problem> target_problem;
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

/// The transferred steps in IPC form, each with the source step it comes from and whether it
/// corresponds or was repaired.
std::string pddl_steps_text(const TransferInputs& in, const transfer::TransferResult& t);

/// What finish_pddl_transfer found: the plans' costs, the comparison with --target-problem and
/// the PDDL validator's verdict, in words (`text`, lines) and for --format json (`json`, the
/// object under "pddl").
struct PddlChecks {
    std::string text;
    nlohmann::ordered_json json = nlohmann::ordered_json::object();
};

/// After a transfer with PDDL inputs: the target plan in IPC form put in `plan_text`, checked by
/// catplan's PDDL validator, and --target-problem compared (what it found added to `checks`),
/// and --problem-output's file added to `outputs`, for the caller to write all or none of;
/// returns kOk, or kNo when the check or the comparison fails.
int finish_pddl_transfer(const TransferInputs& in, const TransferArgs& a,
                         const transfer::TransferResult& t, std::string& plan_text,
                         PddlChecks& checks, std::vector<OutputText>& outputs);

} // namespace catplan::cli
