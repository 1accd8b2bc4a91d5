#pragma once

#include "catplan/acset/acset.hpp"

#include <string>

namespace catplan::acset {

/// The state as one aligned table per object (declaration order), then the variables of each
/// attribute type that has any. Hom cells show the target's name, or #k (1-based) if unnamed.
std::string to_tables(const ACSet& x);

} // namespace catplan::acset
