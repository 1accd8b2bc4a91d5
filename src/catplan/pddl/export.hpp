#pragma once
// catplan -> PDDL, where expressible, so that a standard planner can (re)plan in a catplan domain,
// including one made by migration, and a standard validator can check a plan. docs/pddl-transfer.md
// ("Export") says what each construct becomes; what is left out is said in the output's comments
// and in Exported::notes.
//
// Reading the schema: an *entity object* is one that a hom points into or that carries an
// attribute; a hom between entity objects is an is-a link; every other object is a *fact
// object*, a predicate whose arguments are its homs (its parts are facts: a set). Entity parts
// glued by is-a homs are one *thing*, one PDDL object (a purple block is one thing with a Block
// part, or, migrated into the Kitchenworld, with an Object, a Receptacle and a BreadSliced part).
// Where each entity object has at most one is-a hom the objects are PDDL types (a thing has the
// type of its most specific part); where one has several (BreadSliced is an Object and a
// Receptacle) their component is one PDDL type and each object a unary predicate `(is_O ?x)`.
//
// Attributes: Bool ones are unary predicates (true = the fact holds); the importer's `Name`
// attribute pins a part to the object of that name (a constant); any other attribute that a rule
// or the goal reads has finitely many values (those the domain and problem hold), one unary
// predicate per value (`(hasColor_purple ?x)`); one that nothing reads is left out, and noted.
//
// Markers: a thing that a rule creates or deletes whole (the hand-empty block: unstack deletes it,
// stack makes a new one) cannot be a PDDL object. Such a *shape* (its objects) has at most one
// marker at a time: `(marker_Block)` says it exists, and a fact that refers to it is written
// without that argument (`(Gripper_isHolding_marker)`). Steps that bind a rule's kept part to a
// marker, or that would make a second marker of one shape, are not expressed (noted).
//
// Rules: the kept things of L are the action's parameters (the rule's parameters first); L's
// facts and attribute values are the precondition, NACs adding one fact are negative
// preconditions, deleted, redirected and created facts the effects. Matches are monic, so
// parameters that could be one thing of the same object get `(not (= ?x ?y))`. A rule that does
// not treat facts as sets gets `(not f)` for each fact f it creates (a second equal part is not
// expressed). Rules named `a`, `a~2`, ... (the importer's variants of one PDDL action) are
// exported as one action `a`, as before: PDDL -> catplan -> PDDL keeps the actions and their
// valid plans.
//
// Goals: a goal whose things are all pinned is a PDDL goal. Any other goal is a pattern (its parts
// stand for any things that fit): it becomes an action `reach-goal` whose parameters are the
// goal's things and whose precondition is the goal (with inequalities for monic embedding), the
// goal `(goal-reached)`, and every action requires `(not (goal-reached))`, so that reach-goal is
// the last step of every plan; from_exported_plan leaves it out.

#include "catplan/base/result.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/plan/domain.hpp"

#include <string>
#include <vector>

namespace catplan::pddl {

/// A domain (and problem) as PDDL, with what plan translation needs.
struct Exported {
    std::string domain;  // the domain file
    std::string problem; // the problem file (empty without a problem)
    /// What the export leaves out or does not express, one sentence each (also in the files'
    /// comments).
    std::vector<std::string> notes;
    /// The action that reaches a pattern goal, or empty when the goal is a PDDL goal.
    std::string goal_action;

    /// One exported action made of one rule: its parameters' parts in the rule's L.
    struct Action {
        std::string name;
        const rewrite::Rule* rule = nullptr; // null for an action of several variants
        std::vector<std::pair<ObId, Part>> params;
    };

    std::vector<Action> actions;
    /// The goal's things that are reach-goal's parameters, in order (a part of each).
    std::vector<std::pair<ObId, Part>> goal_params;
    plan::ProblemPtr source;    // the problem exported (null without one)
    plan::DomainPtr domain_ptr; // the domain exported
};

/// Exports the domain and, when given, its problem; fails with the reason (prefixed
/// "not expressible: ") when they cannot be expressed.
Result<Exported> export_pddl(const plan::Domain& domain, const plan::Problem* problem);

/// The domain as a PDDL domain file, or the reason it is not expressible.
Result<std::string> export_domain(const plan::Domain& domain);

/// The problem as a PDDL problem file, or the reason it is not expressible. A pattern goal needs
/// the domain exported with it (export_pddl): its action `reach-goal` is in the domain.
Result<std::string> export_problem(const plan::Problem& problem);

/// A plan of the exported problem replayed with the matches the export expresses.
struct ExportedReplay {
    plan::Plan plan;                         // one argument per rule parameter
    std::vector<hom::ACSetMorphism> matches; // of each step
    std::vector<acset::ACSet> states;        // X_0 .. X_n
    hom::ACSetMorphism goal;                 // the goal's embedding in X_n
};

/// Replays a plan of the exported problem, each step with the match the export expresses (its
/// kept things sent to objects, its deleted things to markers; a step of a migrated rule may name
/// each parameter once, as a transfer prints it), and embeds the goal; fails with the step and
/// the reason. Where catplan's validation finds a step ambiguous (a migrated rule's marker part
/// could also delete a part of an object), this picks the match the export expresses.
Result<ExportedReplay> replay_exported(const Exported& exported, const plan::Plan& plan);

/// A plan of the exported problem in the export's terms (objects named as the export names them,
/// `reach-goal` last when the goal is a pattern); fails when the plan is invalid or a step binds
/// something the export does not express (a marker).
Result<IpcPlan> to_exported_plan(const Exported& exported, const plan::Plan& plan);

/// An IPC plan of the export as a catplan plan of the exported problem (`reach-goal` left out);
/// fails on an unknown action or object, a wrong number of arguments, or a part without a name.
Result<plan::Plan> from_exported_plan(const Exported& exported, const IpcPlan& plan);

} // namespace catplan::pddl
