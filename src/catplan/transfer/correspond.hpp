#pragma once
// The target domain's own actions for the generated ones (semantics.md "Plan transfer", item 6).
//
// A map F : D' -> D generates the target actions Δ_F(a). When the target domain has actions of
// its own (a PDDL domain), each generated action is matched to the target action it *is*: the same
// span up to isomorphism, that is isomorphisms L ≅ L_t, K ≅ K_t and R ≅ R_t that commute with l and
// r, carry every negative (or positive) application condition to one of the target's, and send
// the target's parameters to parts that come from distinct parameters of the source action. Then
// applying the target action at m ∘ φ_L⁻¹ is applying Δ_F(a) at m (up to the names of the parts
// it creates), so the step is carried out in the target's own terms, with its name and its
// parameter order. A map's `actions` section may name the target action of a source action;
// the pair is then checked the same way, and a named pair that is not the same span is reported
// with why.
//
// Attribute expressions are not compared: a rule that has any corresponds to none. A target rule's
// relations (PDDL's facts, merged when added twice) are the target's semantics and are kept.

#include "catplan/base/result.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/plan/domain.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace catplan::transfer {

/// How a generated rule is a target rule.
struct Correspondence {
    rewrite::RulePtr target;
    hom::ACSetMorphism l_iso; ///< Δ_F(L) -> L_t
    hom::ACSetMorphism r_iso; ///< Δ_F(R) -> R_t
    /// Per target parameter: the name of the generated rule's parameter whose part it is.
    std::vector<std::string> parameters;
};

/// The target rule's match that is the generated rule's match m : Δ_F(L) -> Y (m ∘ φ_L⁻¹).
hom::ACSetMorphism transport(const hom::ACSetMorphism& m, const Correspondence& c);

/// The part of the generated rule's R that a part of the target rule's R is (φ_R⁻¹).
Part generated_part(const Correspondence& c, ObId ob, Part target_part);

/// Whether the generated rule is the target rule (the same span up to isomorphism, parameters
/// corresponded), with the isomorphisms; or why not.
Result<Correspondence> corresponds(const rewrite::Rule& generated, const rewrite::RulePtr& target);

/// The target actions, a name per rule for what users read (PDDL's action names), and, per
/// generated rule, the one it corresponds to.
struct TargetActions {
    plan::DomainPtr domain;
    /// The name of a target rule as users know it (`stack` for the rule `stack~2`); empty to use
    /// rule names.
    std::function<std::string(std::string_view rule)> action_name;
    /// The name of a source rule's action (`unstack` for `unstack~2`), to read `named`.
    std::function<std::string(std::string_view rule)> source_action_name;
    /// By generated rule name: its correspondence, or why it has none.
    std::map<std::string, Result<Correspondence>, std::less<>> table;

    /// The correspondence of a generated rule, or nullptr.
    const Correspondence* find(std::string_view generated) const;
    /// What users call a target rule.
    std::string name_of(std::string_view rule) const;
};

/// For each rule of `generated`, the target rule it corresponds to: among the rules of the target
/// action that `named` gives for its source action (source action -> target action), else among
/// all of the target's rules.
TargetActions
correspond_domain(const plan::Domain& generated, plan::DomainPtr target,
                  const std::vector<std::pair<std::string, std::string>>& named,
                  std::function<std::string(std::string_view)> action_name = {},
                  std::function<std::string(std::string_view)> source_action_name = {});

} // namespace catplan::transfer
