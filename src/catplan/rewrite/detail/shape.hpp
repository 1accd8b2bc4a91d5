#pragma once
// What matching (dpo.cpp), the fast in-place application (in_place.cpp) and the reference
// application by colimits (reference.cpp) share: facts about a rule computed once (Rule::shape),
// the validity of a match, and the values a match gives R's variables. Both applications reject a
// match for the same reasons because they ask these same functions.

#include "catplan/colimit/colimit.hpp"
#include "catplan/rewrite/rule.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace catplan::rewrite::detail {

// TODO(#3): merge the kept parts that r sends to one R part (a true pushout).
inline constexpr const char* kGluingKeptParts =
    "rules whose Eff glues two kept parts into one are not supported";

// Facts about a rule that matching and application need, computed at the rule's first match or
// application and kept with it (Rule::shape).
struct Shape {
    explicit Shape(const Rule& rule);

    const Rule& rule;
    std::vector<std::vector<char>> deletes; // per ob, per L part: whether the rule deletes it
    std::vector<std::vector<Part>> k_of_r;  // per ob, per R part: the first K part sent to it
    std::vector<std::uint32_t> unset_in_l;  // per hom: L parts whose value is unset
    std::vector<std::vector<std::uint32_t>> l_incident; // per hom, per L part: |L.incident(h, p)|
    bool r_monic = true;
    /// Whether, for a monic match, the pruning in find_matches already implies the dangling
    /// condition: no hom of L is unset on any part (the pruning allows those), so the only X parts
    /// referring to a deleted part are images of L parts, which a well-formed l deletes too or
    /// keeps with a hom that L and K agree on.
    bool dangling_by_counts = true;
    /// How deleting works for this rule, under DPO and under SPO: the homs it redirects (unset in
    /// K, set in R) are open, so they are no dangling references; SPO rules cascade.
    std::array<colimit::ComplementOptions, 2> gluing_by_semantics;

    bool deleted(ObId o, Part p) const { return deletes[o.index()][p] != 0; }

    /// How deleting works under the rule's semantics now (a rule may be switched to SPO).
    const colimit::ComplementOptions& gluing() const {
        return gluing_by_semantics[rule.semantics == Semantics::SPO ? 1 : 0];
    }
};

/// Whether every object component of m is injective.
bool is_injective(const ACSetMorphism& m, const ACSet& dom);

/// The first failed application condition of m, in words, or nullopt.
std::optional<std::string> condition_problem(const Rule& rule, const ACSet& x,
                                             const ACSetMorphism& m);

/// Everything but naturality and monicity: the gluing conditions (colimit::deletion with the
/// rule's options), then the application conditions.
std::optional<std::string> validity_problem(const Shape& shape, const ACSet& x,
                                            const ACSetMorphism& m);

/// What applying the rule at a valid match needs besides the match, the same for both
/// applications: per attribute type, per variable of R, the value the match gives it (bound
/// through K, or computed by its expression), or unset for a fresh unknown. Fails with the reason
/// when an expression fails, or when the step is not supported: r glues two kept parts, r merges
/// kept values the match binds differently, or the match sends kept parts to one part and Eff
/// gives them different values (the pushout would glue more of X than the match does).
Result<std::vector<std::vector<Value>>> application_values(const Shape& shape,
                                                           const ACSetMorphism& m);

} // namespace catplan::rewrite::detail
