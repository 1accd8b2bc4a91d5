#pragma once
// Data migration Δ_F along a schema map F : D' -> D (schema_map.hpp), on states, morphisms, rules
// and matches.
//
// States. Δ_F(X)(c') is the set of assignments of c's query in X (morphisms Q_c' -> X; the limit
// in Set). Its parts are numbered in lexicographic order of the images of the query's variables,
// in variable order (parts by id, values by kind then value). So a plain entry `c' => c` keeps
// X's order of c, and a filtered one keeps the order of the parts that pass. A tuple takes the
// name of its first object variable's part (`E` stays `E`). A target hom takes each tuple h to
// h ∘ q_f; a target attribute reads its term in X from h (or is its constant). X's attribute
// variables of T are carried as the variables of every T' sent to T, with the same numbers and
// names; a variable never equals a constant, so it never passes a literal filter.
//
// Evaluation: a plain query (delta entry) is X's parts of its object and a delta hom composes
// columns (no search); a query whose shape is a single part with literal filters is a column
// scan; any other query is evaluated by homomorphism search from its shape.
//
// Partial states (a rule's K): an unset hom value of X along a delta hom gives an unset value,
// never a wrong tuple; a query that goes through a hom has no tuple through a part where that hom
// is unset; an unset attribute reads as unset.
//
// Morphisms. Δ_F(α) sends an assignment h of Q_c' in X to α ∘ h, found among the assignments of
// Q_c' in Y (it always is for a morphism α). Attribute-variable components are carried like the
// variables. Rules and matches are migrated through their states and morphisms.

#include "catplan/acset/acset.hpp"
#include "catplan/base/result.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/rewrite/rule.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace catplan::migrate {

namespace detail {
struct Tuples;
} // namespace detail

/// Δ_F(X) together with the assignment behind each of its parts (needed to migrate morphisms
/// into and out of X).
class MigratedState {
public:
    MigratedState();
    MigratedState(MigratedState&&) noexcept;
    MigratedState& operator=(MigratedState&&) noexcept;
    ~MigratedState();

    /// The migrated state, on F's target schema.
    ACSet state;
    /// Per target object (indexed by ObId): how its tuples were found (internal).
    std::vector<std::unique_ptr<detail::Tuples>> tuples;
};

/// Δ_F(X): the state on F's target schema described above. F must be finished and ok.
MigratedState migrate_state(const SchemaMap& f, const ACSet& x);

/// Where each part of Δ_F(X) at target object c starts: the source object of the query's first
/// object variable and, per tuple, the part of X assigned to it (nullopt when the query has no
/// object variable). This is how names flow (a tuple is named after that part).
struct TupleOrigins {
    ObId ob;
    std::vector<Part> parts;
};

std::optional<TupleOrigins> tuple_origins(const SchemaMap& f, const MigratedState& x, ObId c);

/// Δ_F(X) without the bookkeeping.
ACSet migrate(const SchemaMap& f, const ACSet& x);

/// Δ_F(α) : Δ_F(X) -> Δ_F(Y) for a morphism α : X -> Y, given both migrated states; fails with a
/// reason when an assignment's image is not an assignment of Y (α is not natural).
Result<ACSetMorphism> migrate(const SchemaMap& f, const ACSetMorphism& alpha,
                              const MigratedState& x, const MigratedState& y);

/// Δ_F(α) : Δ_F(X) -> Δ_F(Y), migrating X and Y first.
Result<ACSetMorphism> migrate(const SchemaMap& f, const ACSetMorphism& alpha, const ACSet& x,
                              const ACSet& y);

/// Δ_F of a rule: L, K, R, l, r and every application condition (N and n) migrated; each
/// parameter carried by name to every target object that has a tuple named after it (the tuple
/// whose first object variable is the parameter's part), in target object order; expressions
/// carried to each target attribute type sent to the expression's type (an input of a type that
/// no target attribute type is sent to is a Failure).
Result<rewrite::Rule> migrate(const SchemaMap& f, const rewrite::Rule& rule);

/// The target objects whose parts are facts as those of the source relations are (the migrated
/// rule's Rule::relations): each a plain entry on a relation without attributes whose every hom is
/// the one-hom image of a hom of the target object, so that two target parts with equal values
/// come from one source fact. Where an argument is forgotten, Δ_F keeps two facts that agree on
/// the rest, and the target object is not a relation.
std::vector<ObId> migrate_relations(const SchemaMap& f, const std::vector<ObId>& relations);

/// Δ_F of a match m : L -> X of rule: the morphism Δ_F(L) -> Δ_F(X).
Result<ACSetMorphism> migrate_match(const SchemaMap& f, const rewrite::Rule& rule,
                                    const ACSetMorphism& m, const ACSet& x);

} // namespace catplan::migrate
