#pragma once
// Rewriting in the reflective subcategory of states whose relation objects hold each fact once
// (rule.hpp, Rule::relations).
//
// A relation object is one whose parts are determined by their hom and attribute values, as
// PDDL's facts are: the states that hold no two equal parts of it form a reflective subcategory of
// C-sets (the reflection merges equal parts). The pushout complement of such a state is one too,
// so DPO rewriting there is the DPO rewrite in C-sets followed by the reflection, and only the
// parts the rule creates can have become duplicates: each is merged into the equal part already
// there. Adding a fact that holds is then the identity, as PDDL's set semantics has it, with one
// rule and no application condition.

#include "catplan/acset/acset.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/rewrite/rule.hpp"

#include <vector>

namespace catplan::rewrite::detail {

/// Merges each part the rule created in one of its relations into an equal part of x (the
/// created part is removed by pop-and-swap, and r_to_x follows).
void merge_created_facts(const Rule& rule, acset::ACSet& x, hom::ACSetMorphism& r_to_x);

} // namespace catplan::rewrite::detail
