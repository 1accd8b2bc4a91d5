#pragma once
// What `catplan pddl export --map` exports: the domain and problem carried along an ontology map.

#include "catplan/base/result.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/plan/domain.hpp"

#include <utility>

namespace catplan::cli {

/// The domain (and problem, when not null) carried along f: Δ_F of every rule, of the initial
/// state and of the goal; the reason when the domain is not on f's source or a rule cannot be
/// migrated.
Result<std::pair<plan::DomainPtr, plan::ProblemPtr>> migrate_along(const migrate::SchemaMap& f,
                                                                   const plan::DomainPtr& domain,
                                                                   const plan::ProblemPtr& problem);

} // namespace catplan::cli
