#pragma once
// A state whose parts are named, with an index name -> part per object kept in step with every
// rewrite, so that a transfer step costs what it touches, not the size of the state. A name
// shared by two parts of an object is ambiguous: find() answers kNoPart for it.
//
// Names are how a transfer carries matches from the source to the target (transfer.hpp); the
// index is internal to the transfer layer.

#include "catplan/acset/acset.hpp"
#include "catplan/base/result.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/rewrite/dpo.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/transfer/name_index.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace catplan::transfer {

class NamedState {
public:
    explicit NamedState(acset::ACSet x);

    const acset::ACSet& state() const { return x_; }

    /// The state, moved out (the names index is left behind).
    acset::ACSet release() && { return std::move(x_); }

    /// The only part of ob with this name, or kNoPart (none, or several).
    Part find(ObId ob, std::string_view name) const {
        const Part* p = index_[ob.index()].find(name);
        return p == nullptr ? kNoPart : *p;
    }

    /// Whether several parts of ob have this name.
    bool ambiguous(ObId ob, std::string_view name) const {
        const Part* p = index_[ob.index()].find(name);
        return p != nullptr && *p == kNoPart;
    }

    /// Whether any name has been shared by two parts of ob (it then stays taken and ambiguous).
    bool has_ambiguous_names(ObId ob) const { return ambiguous_[ob.index()] > 0; }

    /// Applies rule at m in place, naming each created part with name_of(ob, part of R); returns
    /// the comatch R -> X. CheckMatch::No for a match find_matches (or match_by_names) returned
    /// for this state as it is (rewrite_in_place).
    Result<hom::ACSetMorphism> apply(const rewrite::Rule& rule, const hom::ACSetMorphism& m,
                                     const std::function<std::string(ObId, Part)>& name_of,
                                     rewrite::CheckMatch check = rewrite::CheckMatch::Yes);

    /// A name for a new part of ob, starting from base, that no part of ob has: base, else
    /// base2, base3, ... (the first free one). The search for a suffix starts at a hint per base
    /// below which every suffix is taken, lowered when a name with a smaller suffix is freed, so
    /// that a step costs what it creates, not the number of names sharing the base.
    std::string fresh_name(ObId ob, const std::string& base);

private:
    bool taken(ObId ob, std::string_view name) const {
        return index_[ob.index()].find(name) != nullptr;
    }

    void add(ObId ob, Part p);
    void remove(ObId ob, Part p);
    void moved(ObId ob, Part p, Part survivors);
    void freed(ObId ob, std::string_view name);
    void name_created(const rewrite::Rule& rule, const hom::ACSetMorphism& r_to_x,
                      const std::vector<Part>& survivors,
                      const std::function<std::string(ObId, Part)>& name_of);

    acset::ACSet x_;
    /// Per object: name -> the part that has it (kNoPart when several do).
    std::vector<NameIndex> index_;
    std::vector<std::size_t> ambiguous_; ///< per object, the names that became ambiguous
    /// Per object: for each base fresh_name had to suffix, the smallest suffix that may be free,
    /// sorted by base (a flat array: a repair copies the state at every repaired step).
    std::vector<std::vector<std::pair<std::string, std::uint64_t>>> suffix_hints_;
};

/// The match of a step in x: its arguments bound to the parts of those names (through the index),
/// completed uniquely; else plan::resolve_step's, which says why there is none.
Result<hom::ACSetMorphism> match_by_names(const rewrite::Rule& rule, const NamedState& x,
                                          const plan::Step& step);

} // namespace catplan::transfer
