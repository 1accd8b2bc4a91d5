#pragma once
// Σ_F, the left pushforward along a delta map F : D' -> D (the left adjoint of Δ_F).
//
// Σ_F(Y) is the D-state presented by one generator of object F(c') for each part y of Y at c',
// with the equations F(f)(y) == f(y) for each hom f : c' -> d' of D' and F(a)(y) == a(y) for each
// attribute (a constant, or a variable of Y, shared where Y shares it). As for a free instance,
// every hom of D is defined (a hom no equation fixes gets a new part), every attribute that no
// equation fixes holds a new variable, equal terms are merged (congruence closure) and D's path
// equations hold. So a morphism Σ_F(Y) -> X is the same as a morphism Y -> Δ_F(X):
//
//   Hom(Σ_F Y, X) ≅ Hom(Y, Δ_F X)
//
// In planning terms: a goal G' stated in the target ontology is pushed to the source as Σ_F(G'),
// and a source state reaches Σ_F(G') exactly when its migration reaches G' (up to monicity).
// Parts keep the names of the parts of Y that generate them.
//
//   auto x = sigma(forget_colors, plain_goal);   // a ColorBlocksworld goal with unknown colours

#include "catplan/acset/acset.hpp"
#include "catplan/base/result.hpp"
#include "catplan/migrate/schema_map.hpp"

namespace catplan::migrate {

/// Σ_F(y) for a delta map f and a state y on f's target schema, as a state on f's source; fails
/// with the reason when f is not delta, when two different constants are identified, or when
/// the closure would make more than max_parts parts (D has a cycle of homs, so Σ is infinite).
Result<ACSet> sigma(const SchemaMap& f, const ACSet& y, std::size_t max_parts = 1'000'000);

} // namespace catplan::migrate
