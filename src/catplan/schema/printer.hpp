#pragma once

#include "catplan/schema/schema.hpp"

#include <string>

namespace catplan::schema {

/// The schema as lists: objects, homs, attribute types with their kinds, attributes, equations.
std::string describe(const Schema& s);

} // namespace catplan::schema
