#pragma once
// Repairs already found, by the shape of their focused problem (focus.hpp), so that a transfer
// searches each kind of repair once: the thirty `move`s of a 3-operator blocks-world plan carried
// into the 4-operator domain are a handful of shapes (from a block to a block, from the table to
// a block, ...), and each later one takes the plan of the first, renamed.
//
// The shape of a focused problem (its initial state and its goal, whose parts that homs point into
// are named as their namesakes in the initial state) is the problem with those names replaced by
// numbers: each name gets a colour from the facts, homs and attribute values it takes part in,
// refined a few rounds as in colour refinement (Weisfeiler-Leman), and the names are numbered in
// the order of their colours. Two problems of one shape are the same problem up to renaming, so
// the plan of one, renamed, is a plan of the other. Names that the colours do not tell apart are
// numbered in the order they come in, so that two problems of one shape may still get two keys
// (the memo then misses, and searches); a key is never shared by problems of different shapes.
// Whatever the memo gives is replayed on the whole target state and the subgoal checked
// (repair.cpp), as any plan a search found. Where repairs sum the target's costs, the shape also
// holds the function values a step on its names can read (ValueIndex), so that one shape is one
// problem, costs and all.
//
// A focus keeps the facts about its names that the repair does not change (a block's other
// neighbours, whether it was clear before and after), so the same move in two contexts is two
// shapes. A second memo keys the plans by the shape of the change alone (change_shape); its plan
// is tried, and replayed, before a new search.

#include "catplan/acset/acset.hpp"
#include "catplan/base/symbol.hpp"
#include "catplan/plan/domain.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace catplan::transfer {

/// The target problem's function values by the names they take, so that the shape of a repair
/// whose steps sum costs holds the values its steps can read (two places of one shape then cost
/// the same, and a least-cost plan of one is a least-cost plan of the other).
class ValueIndex {
public:
    /// One value: its function, its arguments, and the value.
    struct Entry {
        Symbol function;
        std::vector<std::string> args;
        std::int64_t value = 0;
    };

    /// Indexes these values, of the functions the costs of the domain's rules read.
    ValueIndex(const std::vector<plan::FunctionValue>& values, const plan::Domain& domain);
    // by_name_ views the strings of entries_, which a move keeps in place and a copy would not.
    ValueIndex(const ValueIndex&) = delete;
    ValueIndex& operator=(const ValueIndex&) = delete;
    ValueIndex(ValueIndex&&) = default;
    ValueIndex& operator=(ValueIndex&&) = default;
    ~ValueIndex() = default;

    /// The values (indices into entries()) that take this name as an argument.
    std::span<const std::uint32_t> of(std::string_view name) const;

    /// Every value indexed.
    const std::vector<Entry>& entries() const { return entries_; }

    /// Whether some rule's cost reads the part of this name by its name (not as a parameter).
    bool read_by_name(std::string_view name) const { return by_name_read_.contains(name); }

private:
    std::vector<Entry> entries_;
    std::set<std::string, std::less<>> by_name_read_;
    std::unordered_map<std::string_view, std::vector<std::uint32_t>> by_name_; ///< into entries_
};

/// A focused problem up to the names of its parts.
struct RepairShape {
    /// Hashes a key.
    struct KeyHash {
        std::size_t operator()(const std::vector<std::uint32_t>& words) const;
    };

    std::vector<std::uint32_t> key;      ///< the same for problems equal up to renaming
    std::vector<std::string_view> names; ///< per number, the name it stands for here
    std::unordered_map<std::string_view, std::uint32_t> number; ///< per name, its number
};

/// The shape of a repair's problem, or nullopt when a part that homs point into has no name
/// (or a goal part no namesake in the initial state); with `values`, the shape also holds the
/// values a step on its names can read: those whose arguments are its names or parts a cost
/// reads by name (held as themselves, since a cost reads them wherever the repair is).
std::optional<RepairShape> repair_shape(const acset::ACSet& initial, const acset::ACSet& goal,
                                        const ValueIndex* values = nullptr);

/// The shape of what a repair's problem changes: the same, without its frame (what it says alike
/// of the initial state and of the goal) and the names only the frame mentions; nullopt as for
/// repair_shape. Problems that differ only in their frame share it, so a plan of one is a guess
/// for the other, which the replay on the whole state then checks.
std::optional<RepairShape> change_shape(const acset::ACSet& initial, const acset::ACSet& goal);

class RepairMemo {
public:
    /// What a search of one shape gave: a plan, or none (unsolvable within the focus's limits).
    struct Entry {
        bool solved = false;
        bool least_cost = false; ///< the plan is one of least cost (the shape holds the values)
        std::size_t origin = 0;  ///< the number of the repair that searched it
        std::vector<std::string> actions;
        std::vector<std::vector<std::uint32_t>> args; ///< per step, its arguments' numbers
    };

    /// The entry of this shape, or nullptr.
    const Entry* find(const RepairShape& shape) const;

    /// Remembers a plan of the shape (its arguments named as shape.names says), and whether it
    /// is one of least cost; a plan with an argument that is none of those names is not
    /// remembered.
    void remember(const RepairShape& shape, const std::vector<plan::Step>& steps,
                  std::size_t origin, bool least_cost = false);

    /// Remembers that the search of the shape found no plan.
    void remember_failure(const RepairShape& shape, std::size_t origin);

    /// The entry's plan with the names of `shape`.
    static std::vector<plan::Step> renamed(const Entry& e, const RepairShape& shape);

private:
    std::unordered_map<std::vector<std::uint32_t>, Entry, RepairShape::KeyHash> entries_;
};

} // namespace catplan::transfer
