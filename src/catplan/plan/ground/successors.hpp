#pragma once
// Which ground actions apply in a state, without trying every action: a decision tree over the
// preconditions (as Fast Downward's successor generator), each action's conditions sorted by
// variable; a node switches on one variable's value and has a child for "any value". The
// forbidden facts and negative conditions of the candidates are checked afterwards.
//
// Applying an action copies the state and sets its effects; an exit action (task.hpp), or one
// that would create an atom already there, does not apply and is reported as leaving the task.

#include "catplan/plan/ground/packed.hpp"

namespace catplan::plan::ground {

class SuccessorGenerator {
public:
    SuccessorGenerator(const Task& task, const StatePacker& packer);

    /// The actions whose preconditions, forbidden facts and negative conditions hold in s
    /// (exits included), in increasing id order.
    void applicable(const Word* s, std::vector<ActionId>& out) const;

    /// Whether a's conditions hold in s (the tree's and the rest).
    bool applies(const Word* s, ActionId a) const;

    std::size_t nodes() const { return nodes_.size(); }

private:
    struct Node {
        VarId var = kNone;                                             // kNone: no switch
        std::vector<std::pair<std::uint32_t, std::uint32_t>> children; // value -> node, sorted
        std::uint32_t any = kNone;                                     // the "any value" child
        std::vector<ActionId> actions; // those with no condition left
    };

    std::uint32_t build(std::vector<std::pair<ActionId, std::uint32_t>> items);
    bool rest_holds(const Word* s, const Action& a) const;

    const Task& task_;
    const StatePacker& packer_;
    std::vector<Node> nodes_;
    mutable std::vector<std::uint32_t> stack_;
};

/// Whether every fact holds in s.
bool holds(const StatePacker& packer, const Word* s, const std::vector<Fact>& facts);

/// Whether s satisfies the task's goal (one term holds).
bool is_goal(const Task& task, const StatePacker& packer, const Word* s);

/// Writes a's successor of s into out; false (out unspecified) when a leaves the task: an exit,
/// or an atom it creates is already present.
bool apply(const Task& task, const StatePacker& packer, const Word* s, ActionId a, Word* out);

} // namespace catplan::plan::ground
