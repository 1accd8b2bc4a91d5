#pragma once
// Colimits of states: coproducts, pushouts and pushout complements (the two halves of a DPO step).
//
//        f           The pushout of B <-f- A -g-> C glues B and C along A: per object, the disjoint
//     A ---> B       union of B's and C's parts with f(a) ~ g(a), closed under the homs (if two
//     parts
//   g |      | ι_B   are glued so are their images). Attribute variables are glued the same way; a
//     v      v       variable glued to a constant takes that constant, and two different constants
//     C ---> P       glued together mean the pushout does not exist (a Failure with the reason).
//         ι_C
//
// Numbering of the result (documented, deterministic): the classes of B's parts in B's order come
// first, then the classes of C's remaining parts in C's order; variables likewise. A glued part
// takes the first non-empty name among its members, B's first.
//
// The pushout complement of K -l-> L -m-> X (l monic) is the state Z = X - m(L - l(K)) with the
// maps K -> Z -> X; it exists when the gluing conditions hold: no deleted part is identified by m
// with another part of L (identification) and no part left in Z refers through a hom to a deleted
// part (dangling). Z keeps X's order (the surviving parts, renumbered from 0) and all of X's
// variables. Violations are reported as data naming the part and the hom.

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

enum class GluingViolationKind { Identification, Dangling, NotMonic };

/// One failed gluing condition, as data.
struct GluingViolation {
    GluingViolationKind kind;
    ObId ob;               // the object of `part`
    Part part = kNoPart;   // Identification: the deleted L part; Dangling: the X part that refers
    Part other = kNoPart;  // Identification: the other L part with the same image
    HomId hom;             // Dangling: the hom through which `part` refers to a deleted part
    Part target = kNoPart; // Dangling: the deleted X part; Identification: the shared X part
    std::string reason;    // the same in words, with part labels
};

/// Every gluing-condition violation of deleting m(L - l(K)) from X (empty when none).
std::vector<GluingViolation> gluing_violations(const ACSet& k, const ACSet& l_state, const ACSet& x,
                                               const ACSetMorphism& l, const ACSetMorphism& m);

struct PushoutComplement {
    ACSet z;
    ACSetMorphism k_to_z; // K -> Z
    ACSetMorphism z_to_x; // Z -> X, the inclusion
};

/// Z = X - m(L - l(K)) with K -> Z -> X, or a Failure listing every gluing violation.
Result<PushoutComplement> pushout_complement(const ACSet& k, const ACSet& l_state, const ACSet& x,
                                             const ACSetMorphism& l, const ACSetMorphism& m);

} // namespace catplan::colimit
