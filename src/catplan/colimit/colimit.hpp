#pragma once
// Colimits of states: coproducts, pushouts and pushout complements (the two halves of a DPO step).
//
// clang-format off
//        f           The pushout of B <-f- A -g-> C glues B and C along A: per object, the
//     A ---> B       disjoint union of B's and C's parts with f(a) ~ g(a), closed under the homs
//   g |      | ι_B   (if two parts are glued so are their images). Attribute variables are glued
//     v      v       the same way; a variable glued to a constant takes that constant, and two
//     C ---> P       different constants glued together mean the pushout does not exist (a
//         ι_C        Failure with the reason).
// clang-format on
//
// Numbering of the result (documented, deterministic; Catlab's, whose pushout is a coproduct of
// the feet in the order [B, C] followed by a coequalizer): the classes of B's parts in B's order
// come first, then the classes of C's remaining parts in C's order; variables likewise. A glued
// part takes the first non-empty name among its members, B's first.
//
// The pushout complement of K -l-> L -m-> X (l monic) is the state Z = X - m(L - l(K)) with the
// maps K -> Z -> X; it exists when the gluing conditions hold: no deleted part is identified by m
// with another part of L (identification) and no part left in Z refers through a hom to a deleted
// part (dangling). Z keeps X's order (the surviving parts, renumbered from 0) and all of X's
// variables. Violations are reported as data naming the part and the hom.
//
// Partial states (a rule's K may leave a cell unset) allow more than one pushout complement: Z
// may keep X's value in a cell of a kept part that K leaves unset, or leave it unset too (L then
// supplies it when L +_K Z is formed). ComplementOptions::open names the cells Z leaves unset: the
// cells a rule rewrites (a hom it redirects, an attribute it sets anew), whose old value must not
// survive into Z; an open hom refers to nothing, so it is never dangling. With
// ComplementOptions::cascade (single-pushout rewriting) the parts of X that refer to a deleted
// part are deleted with it, transitively, instead of violating the dangling condition; Z is then
// the complement of X minus that cascade, and reaching a kept part is a violation.
//
// Gluing checks cost what the deletion touches (the deleted parts and the parts that refer to
// them, through the preimage indexes), not the size of X, so that in-place rewriting can use them.

#include "catplan/acset/acset.hpp"
#include "catplan/base/result.hpp"
#include "catplan/hom/morphism.hpp"

#include <string>
#include <vector>

namespace catplan::colimit {

using acset::ACSet;
using hom::ACSetMorphism;

struct Coproduct {
    ACSet apex;
    ACSetMorphism left;  // B -> B + C
    ACSetMorphism right; // C -> B + C
};

/// Per object, the parts of `codom` outside the image of f, in increasing order: for a rule's
/// l : K -> L the parts it deletes, for r : K -> R the parts it creates.
std::vector<std::vector<Part>> parts_outside_image(const ACSetMorphism& f, const ACSet& codom);

/// The coproduct B + C: B's parts then C's parts, B's variables then C's.
Coproduct coproduct(const ACSet& b, const ACSet& c);

struct Pushout {
    ACSet apex;
    ACSetMorphism left;  // ι_B : B -> P
    ACSetMorphism right; // ι_C : C -> P
};

/// The pushout of B <-f- A -g-> C, or the reason it does not exist (two constants glued).
Result<Pushout> pushout(const ACSet& a, const ACSet& b, const ACSet& c, const ACSetMorphism& f,
                        const ACSetMorphism& g);

/// The cells of K's parts that a pushout complement leaves unset (see the file comment); each
/// must be unset in K too, so that K -> Z is a morphism.
struct OpenCells {
    std::vector<std::vector<Part>> homs;  // per hom (or empty): K parts of its domain, increasing
    std::vector<std::vector<Part>> attrs; // per attribute (or empty): K parts, increasing
};

struct ComplementOptions {
    OpenCells open;
    /// Single-pushout deletion: parts referring to a deleted part are deleted too, transitively.
    bool cascade = false;
    /// Per object, the parts of L outside l(K) (parts_outside_image(l, L)), when the caller keeps
    /// them with the rule; empty: computed at each deletion.
    std::vector<std::vector<Part>> outside_l;
};

enum class GluingViolationKind { Identification, Dangling, NotMonic, Cascade };

/// One failed gluing condition, as data.
struct GluingViolation {
    GluingViolationKind kind;
    ObId ob;               // the object of `part`
    Part part = kNoPart;   // Identification: the deleted L part; Dangling, Cascade: the X part
                           // that refers (Cascade: a kept part the cascade would delete)
    Part other = kNoPart;  // Identification: the other L part with the same image
    HomId hom;             // Dangling, Cascade: the hom through which `part` refers
    Part target = kNoPart; // Dangling, Cascade: the deleted X part; Identification: the shared one
    std::string reason;    // the same in words, with part labels
};

/// What deleting m(L - l(K)) from X removes, and what stands in the way.
struct Deletion {
    std::vector<std::vector<Part>> parts;    // per object: the X parts deleted, increasing
    std::vector<GluingViolation> violations; // in order: not monic, identification, dangling or
                                             // cascade (each by object or hom, then by part)
};

/// Per object, the images under m of the parts of L outside l(K) (`outside_l`, as
/// parts_outside_image(l, L) gives them), increasing and without repeats: what a DPO deletion at
/// m removes.
std::vector<std::vector<Part>> deleted_images(const ACSetMorphism& m,
                                              const std::vector<std::vector<Part>>& outside_l);

/// The parts of X that deleting m(L - l(K)) removes (with the cascade, if asked) and every
/// gluing violation; costs what the deletion touches (the cascade also O(size of X)).
Deletion deletion(const ACSet& k, const ACSet& l_state, const ACSet& x, const ACSetMorphism& l,
                  const ACSetMorphism& m, const ComplementOptions& options = {});

/// Every gluing-condition violation of deleting m(L - l(K)) from X (empty when none).
std::vector<GluingViolation> gluing_violations(const ACSet& k, const ACSet& l_state, const ACSet& x,
                                               const ACSetMorphism& l, const ACSetMorphism& m,
                                               const ComplementOptions& options = {});

struct PushoutComplement {
    ACSet z;
    ACSetMorphism k_to_z; // K -> Z
    ACSetMorphism z_to_x; // Z -> X, the inclusion
};

/// Z = X - m(L - l(K)) with K -> Z -> X (the open cells unset), or a Failure listing every
/// gluing violation.
Result<PushoutComplement> pushout_complement(const ACSet& k, const ACSet& l_state, const ACSet& x,
                                             const ACSetMorphism& l, const ACSetMorphism& m,
                                             const ComplementOptions& options = {});

} // namespace catplan::colimit
