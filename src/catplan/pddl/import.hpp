#pragma once
// PDDL -> catplan: a domain becomes a schema and DPO rules, a problem an initial and a goal state.
//
// Schema. Each type is an object (`object` is the root); a subtype has an is-a hom to its parent
// (`block_is_object`), as the paper's Kitchenworld does; each type carries an attribute
// `<type>_name : Name` holding the PDDL name of the object. A predicate of arity n is an object
// with n homs `<p>_1 .. <p>_n` into its argument types; a nullary predicate is an object without
// homs. A PDDL object `a - block` is one part of `block` and one of each ancestor, linked by the
// is-a homs, all named `a` with name attribute "a"; a fact `(on a b)` is one part of `on`.
//
// The name attribute makes the goal and the domain's constants refer to *these* objects (a
// morphism must preserve concrete values), while a rule's parameters leave it unset, which matches
// any object. It also keeps the planner from merging states that differ only by a permutation of
// objects, which PDDL tells apart.
//
// Rules. One PDDL action becomes several rules (its variants), because two PDDL semantics have no
// direct DPO counterpart:
//   - Parameters may bind the same object, while planning matches are monic: there is one variant
//     per way of identifying parameters (and constants) of compatible types, allowed by the
//     action's `(= ..)` / `(not (= ..))` preconditions; identified parameters are one part, named
//     `x=y`.
//   - A fact is present or not, while DPO creates a new part for every add. For each effect fact
//     that the precondition leaves open (an add or delete of a fact that is not a precondition),
//     there are two variants: the fact is present (it is in L; an add keeps it, a delete removes
//     it) or absent (a NAC forbids it; an add creates it, a delete does nothing). So an add of a
//     fact already true keeps one part, and "delete then add" leaves the fact true, as in PDDL.
// Exactly one variant applies to a ground PDDL step in a state, so plans correspond one to one.
// Negative preconditions are NACs; a fact both added and deleted ends true (add after delete).
// Variants are named `action`, `action~2`, `action~3`, ... (validate.hpp maps steps to them).

#include "catplan/base/diagnostic.hpp"
#include "catplan/pddl/pddl.hpp"
#include "catplan/plan/domain.hpp"

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace catplan::pddl {

/// One rule made from a PDDL action, and how the action's parameters reach the rule's.
struct Variant {
    rewrite::RulePtr rule;
    /// Per PDDL parameter: the index of the rule parameter it binds, or -1 when the variant
    /// identifies it with a constant (then `constant_of` names it).
    std::vector<int> param_of;
    std::vector<std::string> constant_of;
};

struct ActionVariants {
    std::string action;
    std::vector<Variant> variants;
};

/// A PDDL domain (and problem) in catplan form.
struct Import {
    Domain pddl_domain;
    std::optional<Problem> pddl_problem;
    plan::DomainPtr domain;
    plan::ProblemPtr problem; // null when imported without a problem
    std::vector<ActionVariants> actions;
    /// Where PDDL names went in the schema: types, predicates and their argument homs.
    std::unordered_map<std::string, ObId> type_ob, predicate_ob;
    std::unordered_map<std::string, std::vector<HomId>> predicate_homs;

    /// The variants of a PDDL action, or nullptr.
    const ActionVariants* find_action(std::string_view name) const;
    /// The action and variant a rule of the imported domain comes from, or nullopt.
    std::optional<std::pair<const ActionVariants*, const Variant*>>
    find_rule(std::string_view rule_name) const;
};

struct ImportOptions {
    /// At most this many rules per action (the variants grow with parameters and open facts).
    std::size_t max_variants = 4096;
};

/// Imports a domain and, when given, a problem of it; errors (too many variants) go to sink.
std::optional<Import> import_pddl(const Domain& domain, const Problem* problem,
                                  DiagnosticSink& sink, const ImportOptions& options = {});

} // namespace catplan::pddl
