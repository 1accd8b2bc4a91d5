#pragma once
// What can never hold in a PDDL domain, so that the importer leaves out the rules that could never
// apply (import.hpp):
//
// - Invariants (Helmert's monotonicity invariants, "Concise finite-domain representations for
//   PDDL planning tasks", AIJ 2009, in a small form): a set of predicates, each with its
//   arguments split into the invariant's parameters and at most one counted argument, such that
//   for every value of the parameters at most one of its facts holds. The 4-operator blocks
//   world has "at most one of (clear ?b), (holding ?b), (on * ?b)" for every ?b. An invariant is
//   found by guessing and checking: every action that adds one of its facts must delete one of
//   the same parameters that its precondition requires, and no action adds two; a candidate that
//   fails is grown by a fact the action deletes, as Fast Downward's translator does. The check
//   may assume the candidate before the step (it is an induction): an identification of terms
//   under which the precondition holds facts of two of its predicates of one instance cannot
//   apply, so two adds that meet only there, or an add that could restore a deleted fact only
//   there, do not count (stack(x, x) needs (holding x) and (clear x)). It holds in
//   every reachable state when it holds in the initial state (checked for each problem). Two facts
//   of one invariant with the same parameters cannot hold together (a mutex).
// - Argument patterns: which arguments of a fact can name one object ((on ?b ?b) never holds,
//   (link ?x ?x) may). A pattern is a partition of the fact's argument positions; the reachable
//   ones are computed by a fixpoint over the actions without their delete effects, from the
//   initial state's patterns (or, for a domain alone, from the assumption that the initial facts
//   name distinct objects, checked for each problem).
//
// An identification of an action's parameters (a way two of them name one object) whose
// precondition asks for two mutex facts, or for a fact in a pattern that is never reached, can
// never apply; nor can a delete of a fact mutex with the precondition do anything.

#include "catplan/pddl/pddl.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace catplan::pddl {

/// A predicate in an invariant: order[i] is the argument position of the invariant's parameter
/// i; counted is the one other argument position (any value), or -1.
struct InvariantPart {
    std::string predicate;
    std::vector<std::size_t> order;
    int counted = -1;

    friend bool operator==(const InvariantPart&, const InvariantPart&) = default;
};

/// At most one fact of its parts holds for each value of its parameters.
struct Invariant {
    std::size_t arity = 0;
    std::vector<InvariantPart> parts;

    /// "at most one of (clear ?1), (holding ?1), (on * ?1)".
    std::string to_string() const;
    /// The part for a predicate, or nullptr.
    const InvariantPart* find(std::string_view predicate) const;
};

/// The invariants of a domain (those that hold in every state reachable from an initial state
/// that satisfies them), smallest first.
std::vector<Invariant> find_invariants(const Domain& domain);

/// Whether at most one fact of each instance of the invariant holds in these facts.
bool holds_in(const Invariant& invariant, const std::vector<Atom>& facts);

/// A term of an action: a parameter, or a constant its formulas mention.
struct ActionTerm {
    std::string name; // without `?`
    std::string type;
    bool constant = false;
};

/// The action's parameters, in order, then the constants it mentions.
std::vector<ActionTerm> action_terms(const Domain& domain, const Action& action);

/// A fact over the blocks of an identification (ground when each block is one object).
struct BlockFact {
    std::string predicate;
    std::vector<std::size_t> args;
    auto operator<=>(const BlockFact&) const = default;
};

/// One way the terms of an action name objects: term i names the object of block[i]; blocks
/// are numbered in order of first use (a restricted growth string).
struct Identification {
    std::vector<std::size_t> block;
    std::size_t blocks = 0;
    /// The precondition and the effects over the blocks; an atom deleted and added is only added
    /// (PDDL applies deletes first).
    std::vector<BlockFact> pos, neg, add, del;
};

/// What the rules of a domain may assume about its initial states.
struct Assumptions {
    /// The invariants assumed to hold initially (find_invariants, minus those a problem breaks).
    std::vector<Invariant> invariants;
    /// Per predicate (by name): the argument patterns of the initial facts; empty to assume
    /// that every initial fact names distinct objects.
    std::vector<std::pair<std::string, std::vector<std::vector<std::size_t>>>> patterns;
    /// Why the domain's own assumptions did not do for a problem (empty when they did).
    std::vector<std::string> broken;
};

/// The domain's assumptions: its invariants, and initial facts that name distinct objects.
Assumptions domain_assumptions(const Domain& domain);

/// The assumptions for one initial state: the domain's, where the facts satisfy them, else
/// those the facts do satisfy (each broken one said in `broken`).
Assumptions assumptions_for(const Domain& domain, const Assumptions& base,
                            const std::vector<Atom>& initial);

/// The identifications of an action that can apply in some state reachable from an initial state
/// satisfying the assumptions: allowed by the types and the (= ..) literals, with a precondition
/// that is not contradictory, asks for no two mutex facts and no fact in an argument pattern that
/// never holds; deletes of facts mutex with the precondition are dropped. By action, in the
/// domain's order.
std::vector<std::vector<Identification>> applicable_identifications(const Domain& domain,
                                                                    const Assumptions& assumptions);

} // namespace catplan::pddl
