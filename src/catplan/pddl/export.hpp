#pragma once
// catplan -> PDDL, where expressible, so that a standard planner can (re)plan in a catplan domain,
// including one made by migration.
//
// Reading the schema: an *entity type* is an object that is the codomain of a hom or carries an
// attribute; a hom between entity types is an is-a link (at most one per type: PDDL types form a
// tree); every other object is a predicate whose arity is its number of homs, all into entity
// types. A Bool attribute of an entity type is a unary predicate named after it (true = the fact
// holds). Attributes valued in an attribute type named `Name` name objects (the importer's
// convention: a concrete name pins a rule's part to that constant); other attributes (colours,
// masses) are not expressible and are left out, listed in a comment.
//
// Rules: the entities of L are the action's parameters (the rule's parameters first); L's facts
// and Bool values are the precondition, NACs adding one fact are negative preconditions, deleted
// facts and created facts the effects. Matches are monic, so distinct parameters of comparable
// types get `(not (= ?x ?y))`. Rules named `a`, `a~2`, ... (the importer's variants of one PDDL
// action) are exported as one action `a`: facts present in every finest variant are
// preconditions, facts forbidden in every one negative preconditions, the others (open facts)
// only effects, and an inequality is left out when some variant identifies the two parameters.
// So PDDL -> catplan -> PDDL keeps the actions and their valid plans.

#include "catplan/base/result.hpp"
#include "catplan/plan/domain.hpp"

#include <string>

namespace catplan::pddl {

/// The domain as a PDDL domain file, or the reason it is not expressible.
Result<std::string> export_domain(const plan::Domain& domain);

/// The problem as a PDDL problem file (its objects named by their names), or the reason it is
/// not expressible (e.g. a goal part that names no object of the initial state).
Result<std::string> export_problem(const plan::Problem& problem);

} // namespace catplan::pddl
