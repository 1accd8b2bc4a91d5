#pragma once
// Heuristics on a ground task (relaxed.hpp). Each evaluates a state given as one value per
// variable and may name preferred operators (Fast Downward's helpful actions): ground actions the
// search should try first. kDeadEnd means the relaxation cannot reach the goal, so neither can the
// task (exits aside, task.hpp): the search prunes such states.
//
//   blind      0 (1 outside the goal, so greedy search still prefers the goal).
//   goalcount  the goal facts not true (the least over the goal's terms).
//   hadd       h_add (Bonet & Geffner): the sum of the relaxed costs of the goal facts.
//   hmax       h_max: the largest; admissible.
//   hff        h_FF (Hoffmann & Nebel): the relaxed plan built from h_add's best supporters; its
//              actions applicable in the state are the preferred operators.
//   lmcut      LM-cut (Helmert & Domshlak): a sum of disjoint action landmarks' costs; admissible,
//              at least h_max.
//   lmcount    the landmark-count heuristic (landmarks.hpp), path-dependent.

#include "catplan/plan/ground/packed.hpp"
#include "catplan/plan/ground/relaxed.hpp"
#include "catplan/plan/heuristic.hpp"

#include <memory>

namespace catplan::plan::ground {

class Evaluator {
public:
    virtual ~Evaluator() = default;

    /// h of a state (a value per variable), or kDeadEnd; adds preferred operators to `preferred`
    /// when it is not null, chosen from `applicable` when the caller knows them (else null).
    virtual int evaluate(StateId id, const std::vector<std::uint32_t>& state,
                         const std::vector<ActionId>* applicable,
                         std::vector<ActionId>* preferred) = 0;

    /// A path-dependent heuristic learns of each transition (to a state given as a value per
    /// variable) before its target is evaluated; the initial state arrives with parent kNone.
    virtual void reach(StateId parent, ActionId action, StateId child,
                       const std::vector<std::uint32_t>& child_state, bool is_new) {
        (void)parent, (void)action, (void)child, (void)child_state, (void)is_new;
    }

    /// Whether reach must be called (a path-dependent heuristic).
    virtual bool path_dependent() const { return false; }

    /// Whether its values are admissible (A* then finds optimal plans).
    virtual bool admissible() const { return false; }
};

/// A heuristic of this kind (lmcount is made by make_landmark_count, landmarks.hpp).
std::unique_ptr<Evaluator> make_evaluator(HeuristicKind kind, const Task& task,
                                          const RelaxedTask& relaxed, Budget& budget);

} // namespace catplan::plan::ground
