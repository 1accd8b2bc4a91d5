#pragma once
// A transfer's verdict (docs/semantics.md "Plan transfer", steps 1, 3 and 4): whether the
// transferred plan is valid, every fault that makes it invalid, the goal it is judged by with the
// paper's Metric 1, and the claims the transfer makes, each with the hypotheses of the theorem it
// rests on.
//
// The faults are kept in this order, and the first one is the verdict's reason: the step the
// replay stopped at (a source step that does not apply, or a migrated step that does not apply in
// the target), then, with TransferOptions::strict, each step after which the target state is not
// Δ_F of the source state (semantics.md, 3b), then Δ_F(G) not embedding monically in the last
// target state, then the source plan being invalid on its own, then the intended goal (the one
// stated in the target domain, TransferOptions::goal) not being satisfied. Without strict a
// divergence is not a fault, but the verdict carries it (divergences) and every sentence about
// the verdict says so: a transfer whose trajectory diverges is never called valid without it.
// A new way for a transfer to go wrong is a new Fault::Kind; a claim whose theorem needs more
// hypotheses gets more Hypothesis entries, and the first one that fails is the one to name.
//
//   auto t = transfer_plan(map, *problem, plan);
//   const Verdict& v = t.verdict;
//   if (!v.valid()) std::cout << v.reason() << "\n";  // "step 3 pickup(B): no match ..."
//   if (const auto* no = v.claim(Claim::Kind::ValidByConstruction).failing()) ...

#include "catplan/transfer/goal.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace catplan::transfer {

/// One thing that makes a transfer invalid.
struct Fault {
    enum class Kind {
        SourcePlan,   ///< the source plan is invalid on the source problem
        Step,         ///< a step of the source plan applies, but its migration does not
        Goal,         ///< Δ_F(G) does not embed monically in the last target state
        IntendedGoal, ///< the intended goal is not fully satisfied in the last target state
        Divergence,   ///< (strict) after a step, the target state is not Δ_F of the source's
    };
    Kind kind = Kind::Step;
    /// The step it is about (0-based), when it is about one.
    std::optional<std::size_t> step;
    /// The step as "step 3 pickup(B)", when step is set.
    std::string where;
    /// What is wrong, without the step: "no match in the target: ...", "goal not reached: ...".
    std::string why;

    /// "step 3 pickup(B): why", or why alone.
    std::string to_string() const;

    /// The fault a validator's reason says ("step 3 pickup(B): why", or why alone): where is
    /// `where` when the reason starts with it, else empty with the whole reason the why.
    static Fault from_reason(Kind kind, std::optional<std::size_t> step, std::string where,
                             const std::string& reason);
};

/// Where the target trajectory stops being the migration of the source's: after step `step`,
/// Y_i and Δ_F(X_i) are not isomorphic. What differs is named in the words of goal statements
/// (terms.hpp): `Linen l1` is in the target state and not in Δ_F(X_1).
struct Divergence {
    std::size_t step = 0; ///< 0-based: the states after this step differ
    std::string where;    ///< "step 1 relabel(l1)"
    /// Statements of the target state Y_i that Δ_F(X_i) does not make, and the other way round
    /// (at most kMaxListed in all; `more` counts the rest).
    std::vector<std::string> only_in_target, only_in_migrated;
    std::size_t more = 0;

    static constexpr std::size_t kMaxListed = 12;

    /// "it has Linen l1, which Δ_F(X1) has not" (and "Δ_F(X1) has ..., which it has not").
    std::string difference() const;

    /// "the target state after step 1 relabel(l1) is not Δ_F(X1): " + difference().
    std::string to_string() const;
};

/// How the target states are taken (TransferOptions::follow_source).
enum class Trajectory {
    Own,          ///< Y_i is the migrated step applied to Y_{i-1} (Algorithm 1)
    FollowSource, ///< Y_i := Δ_F(X_i); each migrated step is checked to reach it
};

/// A hypothesis of a theorem and whether it holds for this transfer.
struct Hypothesis {
    std::string statement; ///< "F is a delta map (Δ_F preserves pushouts)"
    bool holds = false;
    /// When it does not hold, why, naming what breaks it ("rule pickup has a negative
    /// application condition").
    std::string why_not;
};

/// A guarantee the transfer can give, claimed only when every hypothesis of its theorem holds.
struct Claim {
    enum class Kind {
        /// Every migrated step applies and Y_i = Δ_F(X_i), without search (paper Appendix A):
        /// F is a delta map, every rule the plan uses is a DPO rule without application
        /// conditions, every match is monic, and the source plan is valid.
        ValidByConstruction,
    };
    Kind kind = Kind::ValidByConstruction;
    std::vector<Hypothesis> hypotheses;

    /// Every hypothesis holds.
    bool holds() const;
    /// The first hypothesis that does not hold, or nullptr.
    const Hypothesis* failing() const;
};

/// A transfer's verdict.
struct Verdict {
    enum class Status {
        Valid,   ///< every step applies and the goal (intended, else Δ_F(G)) is met
        Invalid, ///< at least one fault
    };
    Status status = Status::Invalid;
    /// Every fault, in the order described above (empty exactly when valid).
    std::vector<Fault> faults;
    /// The paper's Metric 1 on the last target state reached, for the goal judged by: the
    /// intended goal when one was given, else Δ_F(G).
    GoalSatisfaction goal;
    /// The intended goal's name ("" when the verdict is judged by Δ_F(G)).
    std::string goal_name;
    /// The claims the transfer can make, one per Claim::Kind, with their hypotheses.
    std::vector<Claim> claims;
    /// The steps after which the target state is not Δ_F of the source state: the first one
    /// (Trajectory::Own: the later states are not compared), or each one (FollowSource).
    std::vector<Divergence> divergences;
    Trajectory trajectory = Trajectory::Own;

    bool valid() const { return status == Status::Valid; }

    /// The first divergence, or nullptr when the target states are the migrated source states.
    const Divergence* diverged() const {
        return divergences.empty() ? nullptr : &divergences.front();
    }

    /// Why the transfer is invalid, in one sentence ("" when valid): the first fault,
    /// "the source plan is invalid: step 2 ...", "goal not reached: ...".
    std::string reason() const;

    /// The verdict in one line: "valid: every step applies and the goal embeds monically",
    /// "valid in the target domain, but not the migration of the source plan: the target states
    /// diverge from Δ_F of the source states after step 1 relabel(l1)", "invalid: <reason>".
    std::string summary() const;

    /// The first fault of a kind, or nullptr.
    const Fault* find(Fault::Kind kind) const;

    /// The fault at the step the replay stopped at (source or target), or nullptr.
    const Fault* failed_step() const;

    /// The source plan is valid on the source problem.
    bool source_valid() const { return find(Fault::Kind::SourcePlan) == nullptr; }

    /// The claim of a kind (every kind is present).
    const Claim& claim(Claim::Kind kind) const;
};

/// "the source plan is invalid: <fault>" for a source plan's fault, else the fault in words: the
/// sentence a verdict gives as its reason.
std::string headline(const Fault& fault);

} // namespace catplan::transfer
