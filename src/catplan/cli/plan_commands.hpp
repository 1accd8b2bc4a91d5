#pragma once
// What the `plan` and `validate` commands share between their two inputs: language files
// (commands.cpp) and PDDL files (pddl_commands.cpp).

#include "catplan/plan/search.hpp"

#include <cstddef>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::cli {

/// Whether the positional files of `plan` / `validate` are PDDL (one of them ends in .pddl).
bool is_pddl_input(const std::vector<std::string>& files);
/// `catplan validate DOMAIN.pddl PROBLEM.pddl PLAN`, as text or (json) docs/json-output.md says.
int pddl_validate(const std::vector<std::string>& files, bool json, std::ostream& out,
                  std::ostream& err);
/// `catplan plan DOMAIN.pddl PROBLEM.pddl`: the plan in IPC form.
int pddl_plan(const std::vector<std::string>& files, const plan::SearchOptions& options,
              const std::string& search, const std::string& output, bool timing, bool json,
              std::ostream& out, std::ostream& err);

/// The lines after a plan (or in place of one): the verdict, the search that ran and why, the
/// statistics; each line starts with `comment`.
std::string plan_summary(const plan::SearchResult& r, const std::string& search, std::size_t steps,
                         bool timing, std::string_view comment);
/// A planner run as JSON: status, plan (the given steps), the search, the statistics.
nlohmann::ordered_json plan_json(const plan::SearchResult& r, const std::string& search,
                                 nlohmann::ordered_json steps, bool timing);
/// 0 solved, 1 unsolvable, 4 a limit (docs/exit-codes.md).
int plan_exit_code(plan::SearchStatus status);

} // namespace catplan::cli
