#pragma once
// The tables of the plan library (library.cpp, library_transfer.cpp).

#include "catplan/db/connection.hpp"

namespace catplan::db::detail {

/// The quoted table `name` of the library's namespace "catplan".
std::string library_table(Engine e, std::string_view name);

} // namespace catplan::db::detail
