#pragma once
// Goal satisfaction, the paper's Metric 1 (semantics.md "Plan transfer", step 4).
//
// A goal G is read as statements: each part (`Block A`), each hom value (`on_l(x1) == E`) and
// each concrete attribute value (`hasColor(A) == "purple"`); attribute variables state nothing.
// The figure is the largest fraction of these statements that one injective assignment of G's
// parts to the state's parts satisfies (a part may be left unassigned: its statement and those
// that mention it are then unsatisfied). A monic morphism G -> X satisfies them all.
//
// A monic morphism G -> X (plan::embed_goal) is looked for first. Otherwise the assignment is
// found by branch and bound over G's parts, each next part the one most linked by hom statements
// to the parts placed already, a part's candidates ordered by the statements they satisfy; a node
// limit bounds the work, and when it is reached the figure is a lower bound (exact = false).
// Statements name an unnamed goal part by a term of a named part that reaches it
// (`inReceptacle_r(i1) == plateIsReceptacle(plate)`), else by its label (`#3`).

#include "catplan/acset/acset.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace catplan::transfer {

struct GoalSatisfaction {
    std::size_t satisfied = 0;
    std::size_t total = 0;
    /// The statements the best assignment leaves unsatisfied, in words, in G's order.
    std::vector<std::string> unsatisfied;
    /// False when the node limit stopped the search (satisfied is then a lower bound).
    bool exact = true;

    /// satisfied / total (1 for an empty goal).
    double fraction() const {
        return total == 0 ? 1.0 : static_cast<double>(satisfied) / static_cast<double>(total);
    }
};

/// The statements of a goal, in words, in G's order (parts, then hom values, then attributes,
/// per object).
std::vector<std::string> goal_statements(const acset::ACSet& goal);

/// How many statements goal_statements gives, without putting them in words.
std::size_t count_goal_statements(const acset::ACSet& goal);

/// The paper's Metric 1 for goal in x (same schema); node_limit 0 means no limit.
GoalSatisfaction goal_satisfaction(const acset::ACSet& goal, const acset::ACSet& x,
                                   std::uint64_t node_limit = 1'000'000);

} // namespace catplan::transfer
