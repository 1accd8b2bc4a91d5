#pragma once
// Naming a target state's parts after their types (`--rename-by-type`): a name shared by the
// parts of one entity across target objects (E is an Object, a Receptacle and a BreadSliced) is
// replaced everywhere by the entity's most specific type and a number: bread1, bread2, tomato1.

#include "catplan/acset/acset.hpp"

#include <string>
#include <unordered_map>

namespace catplan::transfer {

using Renaming = std::unordered_map<std::string, std::string>;

/// For each part name of y: the new name after the part's most specific object (the object whose
/// part of that name has an is-a hom to another object's part of that name; else the object with
/// the fewest parts), its first word lowercased, numbered in order of appearance.
Renaming names_by_type(const acset::ACSet& y);

/// Renames every named part of y that the renaming maps.
void rename_parts(acset::ACSet& y, const Renaming& renaming);

/// The renamed name, or the name itself when the renaming does not map it.
std::string renamed(const Renaming& renaming, std::string_view name);

} // namespace catplan::transfer
