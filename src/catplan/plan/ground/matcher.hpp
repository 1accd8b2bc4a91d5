#pragma once
// Matches of a pattern (a rule's L, a goal, a negative condition's N) in the relaxed universe
// (universe.hpp): every way to send its parts to objects and atoms, monic on each object, such
// that each of its hom values, attribute values and variables can hold at once. A match carries
// the facts (var = value, one per variable) under which it is a match in a state; static values
// are checked while matching. Internal to the ground compiler.

#include "catplan/plan/ground/universe.hpp"

#include <functional>

namespace catplan::plan::ground {

struct Pattern {
    const ACSet* p = nullptr;
    /// Per ob, per part: an image fixed in advance (id kNone: free). Empty: none fixed.
    std::vector<std::vector<Image>> fixed;
    /// Per ob, per part: the part is deleted, so it cannot map to an entity. Empty: none.
    std::vector<std::vector<char>> deleted;
    /// Per attribute type, per variable of p: a value bound in advance (unset: free). Empty: none.
    std::vector<std::vector<Value>> bound;
    /// Per attribute type, per variable of p: its value is read by nothing, so it binds kAny
    /// and its cell need only be set. Empty: every variable is read.
    std::vector<std::vector<char>> unread;
    /// Per ob, per part: no hom, attribute or condition of the pattern constrains the part, so
    /// every entity image gives the same transition; only the first free entity is visited
    /// (every slot when none is free). Empty: none.
    std::vector<std::vector<char>> loose;
};

/// The loose parts of a rule's L (Pattern::loose): kept parts of objects that no hom or attribute
/// of L or R touches, of a rule without conditions. Applying the rule at matches that differ only
/// there gives one transition.
std::vector<std::vector<char>> loose_parts(const Universe& u, const Rule& rule);

/// The unread variables of a pattern: those occurring in one cell only (for a rule's L, also
/// not read by an expression, not carried to another cell, and the rule has no conditions).
std::vector<std::vector<char>> unread_variables(const ACSet& p, const Rule* rule);

struct Match {
    std::vector<std::vector<Image>> images;   // per ob, per part
    std::vector<std::vector<Value>> bindings; // per attribute type, per variable of p
    std::vector<Fact> facts;                  // unsorted, one per variable
};

/// Calls visit on every match of the pattern; visit returns false to stop.
void for_each_match(const Universe& u, const Pattern& pattern,
                    const std::function<bool(const Match&)>& visit);

} // namespace catplan::plan::ground
