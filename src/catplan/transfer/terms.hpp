#pragma once
// Words for parts, for people: a part is called by the name a person gave it, else by a term of
// a part a person named that reaches it in one hom (`isEmpty(empty)` for the hand-empty marker,
// `plateIsReceptacle(plate)`), else by its label (`#3`). Goal statements, the bindings of a
// transferred step and the differences of a divergent trajectory all name parts this way.
//
// Names that catplan makes up are not a person's: a part's label (`#7`, given to an unnamed part
// of the initial state so that names can carry every part), the name of a part a step created
// that its rule does not name (`block@2`: a Block created by step 2), and the name a PDDL action's
// fact takes in its rule (`(clear y)`). They contain '#', '@' or '(', which no identifier of the
// language or of PDDL can. A fact no person named is called by its tuple: `clear(a)`.

#include "catplan/acset/acset.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/migrate/migration.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::transfer {

/// Whether a part name was written by a person (not empty, and not one catplan makes up).
bool is_user_name(std::string_view name);

/// A part that is nothing but the tuple of its homs (its object has homs, all set at p, and no
/// attribute, and no hom points into it: a PDDL fact, a relation's row) called by that tuple,
/// `on(a, b)`; nullopt for any other part.
std::optional<std::string> tuple_term(const acset::ACSet& x, ObId ob, Part p);

/// Words for part p of ob in x, best first: its name when a person wrote it; else `f(n)` for
/// every hom f and part named n by a person with f(that part) == p, ordered by the part's object,
/// the part, then f; then its tuple_term; last the part's name or label (so the list is never
/// empty).
std::vector<std::string> part_words(const acset::ACSet& x, ObId ob, Part p);

/// Whether part p of ob has a word a person can read: a name a person wrote or a term, not only
/// its label or a name catplan made up (`block@2`).
bool has_readable_word(const acset::ACSet& x, ObId ob, Part p);

/// The first of part_words (`_` for kNoPart).
std::string part_word(const acset::ACSet& x, ObId ob, Part p);

/// The statement that part p of ob exists: `Block A`.
std::string part_statement(const acset::ACSet& x, ObId ob, Part p);

/// The statement of hom f at part p: `on_l(x1) == E`; its value is named by its first word other
/// than the term itself (`isHolding(gripper) == isEmpty(empty)`, not `== isHolding(gripper)`).
std::string hom_statement(const acset::ACSet& x, HomId f, Part p);

/// The statement of attribute a at part p: `hasColor(A) == "purple"`, or `hasColor(A) == ?` when
/// the value is unknown (a variable).
std::string attr_statement(const acset::ACSet& x, AttrId a, Part p);

/// Everything x states about part p of ob: the part, then each set hom and each set attribute
/// in schema order; for a part no person named that has a tuple_term, that term alone.
std::vector<std::string> part_statements(const acset::ACSet& x, ObId ob, Part p);

/// Where each part of a migrated rule's L starts, by target object (migrate::tuple_origins).
using LOrigins = std::vector<std::optional<migrate::TupleOrigins>>;

/// A match m : L -> X in words (plan::describe_match), each part called by part_word
/// (`block ↦ E, isEmpty(empty) ↦ isEmpty(empty)`), then each variable of L with its value. With
/// `origins`, the parts of L that start at one source part are one binding, called by the first
/// of them that has more than a label (the hand-empty marker's Receptacle part as
/// `isEmpty(empty)`, after its Object part, not `#3 ↦ #7`).
std::string describe_bindings(const hom::ACSetMorphism& m, const acset::ACSet& l,
                              const acset::ACSet& x, const LOrigins* origins = nullptr);

} // namespace catplan::transfer
