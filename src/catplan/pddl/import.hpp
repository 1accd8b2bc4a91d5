#pragma once
// PDDL -> catplan: a domain becomes a schema and DPO rules, a problem an initial and a goal state.
//
// Schema. Each type is an object (`object` is the root); a subtype has an is-a hom to each parent
// (`block_is_object`), as the paper's Kitchenworld does; each type carries an attribute
// `<type>_name : Name` holding the PDDL name of the object. A union type `(either a b)` is the
// object `either_a_b`, with the homs `a_is_either_a_b` and `b_is_either_a_b` from its members
// (pddl.hpp), so that its parts are exactly the objects of type a or b. A predicate of arity n
// is an object with n homs `<p>_1 .. <p>_n` into its argument types; a nullary predicate is an
// object without homs. A PDDL object `a - block` is one part of `block` and one of each ancestor,
// linked by the is-a homs, all named `a` with name attribute "a"; a fact `(on a b)` is one part of
// `on`.
//
// Costs. A domain whose actions say what they cost (`(increase (total-cost) ...)`) gives every
// rule a rewrite::Cost (0 for an action that says nothing): its constant, and the function terms
// that depend on a problem's values, as written; costs.hpp computes a ground step's cost.
//
// Goals. A problem's negative goal `(not (on a b))` is a goal condition (plan::Problem's
// goal_conditions): the goal with the fact added, which must not extend the goal's embedding.
//
// The name attribute makes the goal and the domain's constants refer to *these* objects (a
// morphism must preserve concrete values), while a rule's parameters leave it unset, which matches
// any object. It also keeps the planner from merging states that differ only by a permutation of
// objects, which PDDL tells apart.
//
// Rules. A PDDL action becomes one rule, or a handful (its variants), because two PDDL semantics
// have no direct DPO counterpart:
//   - A fact is present or not, while DPO creates a new part for every add. The rules' predicate
//     objects are relations (rewrite::Rule::relations): a created fact that is already there is
//     merged into it, which is DPO rewriting in the reflective subcategory of states that hold
//     each fact once. So an add needs no variant and no condition. A delete of a fact the
//     precondition leaves open needs two variants: the fact is present (it is in L and deleted)
//     or absent (a NAC forbids it; nothing happens), unless the fact is mutex with the
//     precondition (analysis.hpp), when only "absent" can happen and the delete is dropped.
//   - Parameters may bind the same object, while planning matches are monic: there is one
//     variant per way of identifying parameters (and constants) of compatible types that the
//     action's `(= ..)` / `(not (= ..))` allow and that can apply (analysis.hpp: no mutex facts
//     in its precondition, no fact in an argument pattern that never holds, such as (on ?b ?b)).
//     Identified parameters are one part, named `x=y`.
// Exactly one variant applies to a ground PDDL step in a state, so plans correspond one to one.
// Negative preconditions are NACs; a fact both added and deleted ends true (add after delete).
// The 4-operator blocks world has four rules, one per action. Variants are named `action`,
// `action~2`, ...; each says which action it carries out (rewrite::ActionOf), and everything
// shown to a user names the action (plan/actions.hpp, `to_ipc_plan`, `action_of`).
//
// The analysis assumes that the initial state satisfies the domain's invariants and that its
// facts name distinct objects (Assumptions). A problem that does not gets rules of its own, on
// the same schema (import_problem), and Import::assumptions.broken says why.

#include "catplan/base/diagnostic.hpp"
#include "catplan/pddl/analysis.hpp"
#include "catplan/pddl/pddl.hpp"
#include "catplan/plan/domain.hpp"

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace catplan::pddl {

/// One rule made from a PDDL action; its rewrite::ActionOf says how the action's parameters
/// reach the rule's (a parameter identified with a constant is that constant's name).
struct Variant {
    rewrite::RulePtr rule;
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
    /// Where PDDL names went in the schema: types (with their is-a hom to the parent and their
    /// name attribute), predicates and their argument homs, and the attribute type of names.
    std::unordered_map<std::string, ObId> type_ob, predicate_ob;
    /// Per type: its is-a homs, one per parent (Type::parents' order).
    std::unordered_map<std::string, std::vector<HomId>> is_a;
    std::unordered_map<std::string, AttrId> name_attr;
    std::unordered_map<std::string, std::vector<HomId>> predicate_homs;
    AttrTypeId name_type;
    /// What the rules assume of the initial state.
    Assumptions assumptions;

    /// The variants of a PDDL action, or nullptr.
    const ActionVariants* find_action(std::string_view name) const;
    /// The action and variant a rule of the imported domain comes from, or nullopt.
    std::optional<std::pair<const ActionVariants*, const Variant*>>
    find_rule(std::string_view rule_name) const;
    /// The PDDL action a rule of the imported domain comes from ("stack" for `stack~2`), or the
    /// rule's own name.
    std::string action_of(std::string_view rule_name) const;
    /// The type a schema object stands for, or nullptr.
    const std::string* type_of(ObId ob) const;
    /// The predicate a schema object stands for, or nullptr.
    const std::string* predicate_of(ObId ob) const;
    /// The facts of a state on the imported schema, as ground atoms (objects by part name).
    std::vector<Atom> facts(const acset::ACSet& x) const;
};

struct ImportOptions {
    /// At most this many rules per action (the variants grow with parameters and open deletes).
    std::size_t max_variants = 4096;
};

/// Imports a domain and, when given, a problem of it; errors (too many variants) go to sink.
std::optional<Import> import_pddl(const Domain& domain, const Problem* problem,
                                  DiagnosticSink& sink, const ImportOptions& options = {});

/// A problem of an imported domain, on the same schema: the import with the problem's states,
/// and with rules of its own when the problem breaks the domain's assumptions.
std::optional<Import> import_problem(const Import& domain, const Problem& problem,
                                     DiagnosticSink& sink, const ImportOptions& options = {});

/// A problem's function values as the rules' costs read them (total-cost's left out).
std::vector<plan::FunctionValue> function_values(const std::vector<FunctionValue>& values);

/// The import's rules for an initial state given as facts: the same rules when the facts meet
/// the import's assumptions, else rules rebuilt for them on the same schema.
std::optional<Import> for_initial_facts(const Import& domain, const std::vector<Atom>& facts,
                                        DiagnosticSink& sink, const ImportOptions& options = {});

} // namespace catplan::pddl
