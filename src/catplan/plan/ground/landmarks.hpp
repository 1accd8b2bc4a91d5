#pragma once
// Landmarks of a ground task and the landmark-count heuristic (Richter & Westphal's LAMA).
//
// A landmark is a fact, or a set of facts (disjunctive) one of which, that every plan makes true
// at some point. They are found by back-chaining from the goal (Hoffmann, Porteous & Sebastia;
// Richter, Helmert & Westphal): for a landmark not true initially, its possible first achievers
// are the achievers reachable in the relaxation without it; the preconditions they all share are
// landmarks ordered greedy-necessarily before it. Disjunctive landmarks come from a variable that
// every first achiever needs (with different values), and, as RHW's disjunction classes, from
// atoms of one predicate one of which every first achiever needs (gripper's (carry ?b left) or
// (carry ?b right)); at most four facts, none true initially, and a disjunction that shares a
// fact with one found before is dropped (as Fast Downward does).
//
// The heuristic counts, per state, the landmarks not yet accepted plus the accepted ones needed
// again (false now, and a goal or greedy-necessarily before one not accepted). A landmark is
// accepted on a path when it holds after a step whose source had accepted all its predecessors;
// a state reached by several paths keeps what all of them accepted. Preferred operators: the
// applicable actions that achieve a landmark not accepted or needed again.

#include "catplan/plan/ground/heuristics.hpp"

namespace catplan::plan::ground {

struct Landmark {
    std::vector<Fact> facts;            // one fact, or the facts of a disjunctive landmark
    std::vector<std::uint32_t> parents; // greedy-necessary predecessors
    std::vector<std::uint32_t> children;
    bool goal = false;
    std::vector<std::uint32_t> achievers; // relaxed actions adding one of the facts
};

/// The landmarks of the task (every fact of the goal included), found as above.
std::vector<Landmark> find_landmarks(const Task& task, const RelaxedTask& relaxed, Budget& budget);

/// The landmark-count heuristic.
std::unique_ptr<Evaluator> make_landmark_count(const Task& task, const RelaxedTask& relaxed,
                                               Budget& budget);

/// LM-cut (heuristics.hpp).
std::unique_ptr<Evaluator> make_lm_cut(const RelaxedTask& relaxed, Budget& budget);

} // namespace catplan::plan::ground
