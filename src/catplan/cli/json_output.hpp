#pragma once
// The JSON the commands print with `--format json` (docs/json-output.md): states and schemas as
// Catlab's JSON (json/json.hpp), morphisms and matches as objects from the parts of their domain
// to the parts of their codomain, plan steps as objects.

#include "catplan/acset/acset.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/schema/schema.hpp"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace catplan::cli {

/// A state as Catlab's ACSet JSON, with part names ("_name"), as a JSON value.
nlohmann::ordered_json acset_value(const acset::ACSet& x);

/// A schema as Catlab's schema JSON, as a JSON value.
nlohmann::ordered_json schema_value(const schema::Schema& s);

/// {"Ob": {"a": "b", ...}, "AttrType": {...}}: for each object (and attribute type) with parts
/// in x, each part's label in x with the label of its image in y.
nlohmann::ordered_json morphism_json(const hom::ACSetMorphism& f, const acset::ACSet& x,
                                     const acset::ACSet& y);

/// {"action", "arguments"}, and "match" when `match` is not null.
nlohmann::ordered_json step_json(const std::string& action,
                                 const std::vector<std::string>& arguments,
                                 nlohmann::ordered_json match = nullptr);

/// {"kind", "name", "summary"} of a declaration (kind as `catplan check` names it: "schema", ...).
nlohmann::ordered_json declaration_json(const lang::Declaration& d);

/// The JSON text a command prints: indented by 2, one newline at the end.
std::string json_text(const nlohmann::ordered_json& doc);

/// A plan's validation as `catplan validate --format json` prints it: "valid", "goal_reached",
/// "steps" (the steps that applied, step_json each), "failed_step" (null, or {"index" (0-based),
/// "location"}) and "reason" ("" when valid).
nlohmann::ordered_json validation_json(bool valid, bool goal_reached,
                                       std::optional<std::size_t> failed_step,
                                       const std::string& reason, const std::string& location,
                                       nlohmann::ordered_json steps);

/// The steps of `steps` that applied in the validation `v` (made with keep_states), each as
/// step_json with its match (morphism_json from the rule's L to the state it applied to).
nlohmann::ordered_json validated_steps_json(const plan::Problem& problem,
                                            const std::vector<plan::Step>& steps,
                                            const plan::Validation& v);

} // namespace catplan::cli
