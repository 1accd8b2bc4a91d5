#pragma once
// The focus of a repair (repair.hpp): the repair's problem restricted to the parts of the target
// state near what the subgoal changes, so that a repair costs what the step touches rather than
// the size of the state.
//
// The subgoal Δ_F(X_i) and the target state Y_{i-1} name their parts alike (transfer.hpp), so they
// are compared by names: a part of an object that homs point into (a block, a PDDL object) is its
// namesake in Y, and differs from it when a hom value (by the name of its target) or a concrete
// attribute value differs; a part of an object nothing points into (a fact, `on(a, b)`) is present
// in Y when a part of Y has the same hom values and concrete attribute values. The seeds are the
// parts of Y that differ and the arguments of the facts Y lacks.
//
// The problem of radius r keeps the parts of Y within r steps of a seed (a step: a hom between
// two such parts, either way, or a fact holding both), every part they point to (along homs, in Y
// and in the subgoal), and the facts whose arguments are all kept; the goal keeps the subgoal's
// parts whose namesakes are kept. A plan of the focused problem changes only kept parts and facts
// among them, and every fact of the subgoal outside the focus already holds in Y. It may still
// fail in Y (a negative condition, or a dangling part, that the focus does not see), so the repair
// replays it on Y and checks the whole subgoal (repair.cpp) before it is used.

#include "catplan/acset/acset.hpp"
#include "catplan/base/result.hpp"
#include "catplan/transfer/named_state.hpp"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace catplan::transfer {

class Focus;

/// Whether goal embeds monically in x by a morphism that sends each part of an object that homs
/// point into to its namesake in x (a search that has only the facts left to place).
bool embeds_by_names(const NamedState& x, const acset::ACSet& goal);

/// A repair's problem restricted to a neighbourhood of what the subgoal changes.
struct FocusedProblem {
    acset::ACSet initial; ///< the kept parts of Y, named as in Y
    acset::ACSet goal;    ///< the parts of the subgoal whose namesakes are kept
    /// The kept parts of objects that homs point into (the facts among them not counted).
    std::size_t parts = 0;
    /// Every part of Y is kept: the focused problem is the whole repair.
    bool whole = false;
};

class Focus {
public:
    /// How much of the subgoal Focus::of compares: all of it, or up to its first part that
    /// differs (enough to tell whether y holds the subgoal by names; no problem() then).
    enum class Scan { Whole, FirstDifference };

    /// The parts of y that differ from subgoal (none, and no fact lacking: y holds the subgoal
    /// by names, unless shared_fact()), or why the subgoal cannot be compared with y by names (a
    /// part without a name or without a namesake in y).
    static Result<Focus> of(const NamedState& y, const acset::ACSet& subgoal,
                            Scan scan = Scan::Whole);

    /// Whether some part of the subgoal differs from y by names: a seed, or a fact y lacks (one
    /// of no arguments seeds no part).
    bool differs() const { return !seeds_.empty() || lacks_fact_; }

    /// Whether two facts of the subgoal are the same fact of y (so that "no difference" does not
    /// mean that the subgoal embeds monically).
    bool shared_fact() const { return shared_fact_; }

    /// The problem on the parts of Y within `radius` steps of a seed (of a Scan::Whole focus).
    FocusedProblem problem(std::size_t radius) const;

    /// How many parts of Y differ from the subgoal or are arguments of a fact Y lacks.
    std::size_t seeds() const { return seeds_.size(); }

private:
    Focus(const NamedState& y, const acset::ACSet& subgoal);

    struct Columns;

    std::optional<std::string> match_names(const NamedState& y);
    void find_seeds();
    bool seed_object(ObId ob, Columns& cols);
    Part fact_in_y(ObId ob, const Columns& cols, Part p) const;
    void seed(ObId ob, Part q);
    void close(std::vector<std::vector<char>>& keep) const;
    FocusedProblem make_problem(std::vector<std::vector<char>> keep) const;

    /// One row of T per object, the rows in one array (a focus is made at every repaired step:
    /// one allocation, not one per object). Filled object by object with append().
    template <class T>
    struct Rows {
        std::vector<T> cells;
        std::vector<std::size_t> start{0}; // row o is cells[start[o], start[o + 1])

        void reserve(std::size_t rows, std::size_t n) {
            start.reserve(rows + 1);
            cells.reserve(n);
        }

        void append(std::size_t n, T value) {
            cells.resize(cells.size() + n, value);
            start.push_back(cells.size());
        }

        std::span<T> operator[](std::size_t o) {
            return {cells.data() + start[o], start[o + 1] - start[o]};
        }

        std::span<const T> operator[](std::size_t o) const {
            return {cells.data() + start[o], start[o + 1] - start[o]};
        }
    };

    const acset::ACSet* y_;
    const acset::ACSet* goal_;
    /// Per object that homs point into, per part of the subgoal: its namesake in Y.
    Rows<Part> namesake_;
    /// Per object that homs point into, per part of Y: the subgoal part it is the namesake of.
    Rows<Part> goal_part_;
    std::vector<std::pair<ObId, Part>> seeds_; // parts of Y
    /// Per object, per part of Y: seeded (pointed objects), or found by a fact of the subgoal.
    Rows<char> seeded_;
    bool shared_fact_ = false;
    bool lacks_fact_ = false; ///< a fact of the subgoal that y lacks
    Scan scan_ = Scan::Whole;
};

} // namespace catplan::transfer
