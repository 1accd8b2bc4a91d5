#pragma once
// Morphisms of states (natural transformations α : X -> Y between attributed C-sets).
//
// A morphism has one component per object (dom part -> codom part) and, per attribute type, a
// map from the domain's attribute variables to codomain values: a concrete value or a codomain
// variable. Concrete values are mapped to themselves. Naturality means, for every hom f : A -> B
// and part x of A, α_B(X.f(x)) == Y.f(α_A(x)), and for every attribute a : A -> T,
// β_T(X.a(x)) == Y.a(α_A(x)), where β_T is the identity on concrete values.
//
// Unset cells of the domain impose no constraint: a hom value kNoPart or an unset attribute cell
// in X says nothing about the image (the same rule the homomorphism search uses).
//
//   ACSetMorphism id = identity(x);
//   auto problems = naturality_failures(f, x, y);   // empty when natural
//   for (auto& p : problems) std::puts(describe(p, x, y).c_str());

#include "catplan/acset/acset.hpp"
#include "catplan/acset/value.hpp"
#include "catplan/base/id.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace catplan::hom {

using acset::ACSet;
using acset::Value;

struct ACSetMorphism {
    /// Per object (indexed by ObId): the image of each domain part.
    std::vector<std::vector<Part>> components;
    /// Per attribute type (indexed by AttrTypeId): the image of each domain variable.
    std::vector<std::vector<Value>> var_components;

    /// The image of part p of object x.
    Part operator()(ObId x, Part p) const { return components[x.index()][p]; }

    /// The image of variable j of attribute type t.
    const Value& var(AttrTypeId t, std::uint32_t j) const { return var_components[t.index()][j]; }

    friend bool operator==(const ACSetMorphism&, const ACSetMorphism&) = default;
};

/// The identity morphism of x: every part and every variable goes to itself.
ACSetMorphism identity(const ACSet& x);

/// The composite g∘f (first f, then g). A variable sent by f to a codomain variable k is sent on
/// to g's image of k; a concrete value stays. Asserts that the components compose.
ACSetMorphism compose(const ACSetMorphism& f, const ACSetMorphism& g);

/// What went wrong at one place of a morphism.
enum class NaturalityFailureKind : std::uint8_t {
    ComponentSize,    // components[ob] has the wrong length (part = its length)
    PartOutOfRange,   // components[ob][part] is not a part of Y (found = the bad image)
    HomMismatch,      // α_B(X.f(x)) != Y.f(α_A(x)); expected = Y.f(α_A(x)), found = α_B(X.f(x))
    VarComponentSize, // var_components[type] has the wrong length (part = its length)
    VarImageInvalid,  // a variable sent to unset or to a variable Y does not have
    VarImageWrongKind, // a variable sent to a concrete value of the wrong kind for its type
    AttrMismatch, // β(X.a(x)) != Y.a(α(x)); expected_value = β(X.a(x)), found_value = Y.a(α(x))
};

/// One naturality failure, as data. Fields that do not apply to the kind keep their defaults.
struct NaturalityFailure {
    NaturalityFailureKind kind = NaturalityFailureKind::ComponentSize;
    ObId ob;             // the object of `part` (ComponentSize, PartOutOfRange, Hom/AttrMismatch)
    HomId hom;           // HomMismatch
    AttrId attr;         // AttrMismatch
    AttrTypeId type;     // VarComponentSize, VarImageInvalid, VarImageWrongKind, AttrMismatch
    Part part = kNoPart; // the domain part (or variable index) where it fails
    Part expected = kNoPart; // HomMismatch: Y.f(α_A(x)); ComponentSize: the length it should have
    Part found = kNoPart;    // HomMismatch: α_B(X.f(x)); PartOutOfRange: the image
    Value expected_value;    // AttrMismatch
    Value found_value;       // AttrMismatch, VarImageInvalid, VarImageWrongKind
};

/// Every naturality failure of f : x -> y (wrong sizes, out-of-range images, hom and attribute
/// squares that do not commute), in schema order; empty when f is a morphism.
std::vector<NaturalityFailure> naturality_failures(const ACSetMorphism& f, const ACSet& x,
                                                   const ACSet& y);

/// One failure in words, with parts labelled by name (or #n) in x and y.
std::string describe(const NaturalityFailure& failure, const ACSet& x, const ACSet& y);

/// Whether f : x -> y is a morphism (naturality_failures is empty).
bool is_natural(const ACSetMorphism& f, const ACSet& x, const ACSet& y);

/// Whether every object component of f is injective (attribute components are not considered).
bool is_monic(const ACSetMorphism& f, const ACSet& x, const ACSet& y);

/// Whether every object component is a bijection onto y's parts and every variable component a
/// bijection onto y's variables (naturality is not checked here).
bool is_iso(const ACSetMorphism& f, const ACSet& x, const ACSet& y);

} // namespace catplan::hom
