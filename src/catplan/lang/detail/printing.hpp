#pragma once
// What the printers of instances (printer.cpp) and of rules, domains and problems
// (rule_printer.cpp) share: the generator names of a state's parts, and the statements of a block
// that extends another state.

#include "catplan/acset/acset.hpp"
#include "catplan/hom/morphism.hpp"

#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::lang::detail {

/// Per object, per part: a generator name (unquoted).
using PartNames = std::vector<std::vector<std::string>>;

/// Generator names that must be distinct: those of one printed state, or of all the states of
/// one rule (so that no block's name stands for a part of another by accident).
class NamePool {
public:
    bool used(const std::string& n) const { return used_.count(n) != 0; }

    void add(const std::string& n) { used_.insert(n); }

    /// `wanted` when it is free and can be written, else generated_name's, made free.
    std::string take(std::string_view wanted, std::string_view kind, std::uint32_t index);

private:
    std::set<std::string> used_;
};

/// The names print_instance gives x's parts and variables: their own where distinct and writable
/// (the parts of `name_first` choose first), else generated_name's.
struct StateNames {
    PartNames parts;
    PartNames vars; // per attribute type, per variable
};

StateNames state_names(const acset::ACSet& x, std::span<const ObId> name_first);

/// What a block says of a state x: the parts to declare, and the cells that the state it extends
/// (`from`, along a morphism whose preimages are `pre`) does not already give. Without `from`,
/// every part and set cell.
struct BlockView {
    const acset::ACSet* x;
    const PartNames* names;
    const acset::ACSet* from = nullptr;
    std::vector<std::vector<Part>> pre = {}; // per part of x: its preimage in `from`, or kNoPart
};

/// Per object, per part of y: the part of x that f : x -> y sends to it, or kNoPart.
std::vector<std::vector<Part>> preimages(const hom::ACSetMorphism& f, const acset::ACSet& x,
                                         const acset::ACSet& y);

/// The statements of the block, one per line after `indent`: declarations `(a, b)::T`, then
/// `f(a) == b` and `attr(a) == literal`. The state must have no variables.
std::string block_statements(const BlockView& b, std::string_view indent);

} // namespace catplan::lang::detail
