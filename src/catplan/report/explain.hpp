#pragma once
// Why a transferred plan is the analogue of its source plan, in words (the paper's Metric 2,
// "explainability"): what the map sends each target object to and what it loses, and for each
// step why every target part bound is the image of the source part bound. Data and strings
// only, so that they can be tested without a page; report.cpp lays them out.
//
//   auto brief = summarize_map(map);   // brief.objects: "BreadSliced ⇒ {block::Block | ...}"
//   for (const auto& g : brief.lost) ... // "isClear", "isOnTable": nothing maps onto them
//   auto why = binding_reasons(map, *source_rule, *target_rule, step, x, y);
//   // "E ↦ BreadSliced E because hasColor(E) == \"purple\" and BreadSliced ⇒ {...}"

#include "catplan/dot/dot.hpp"
#include "catplan/migrate/describe.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/transfer/transfer.hpp"

#include <string>
#include <vector>

namespace catplan::report {

/// A source generator that no target generator maps onto (its information is lost).
struct LostGenerator {
    schema::Generator source;
    std::string name;
};

/// The map in brief: each target object with its image, and what the map does not see.
struct MapSummary {
    /// The target objects' lines of migrate::describe_map, in the target schema's order.
    std::vector<migrate::MapLine> objects;
    /// Source objects, homs, attribute types and attributes (in that order, each in schema
    /// order) that no image uses: Δ_F forgets them.
    std::vector<LostGenerator> lost;
};

/// The brief of a finished map.
MapSummary summarize_map(const migrate::SchemaMap& f);

/// The lost generators of one kind, by name ("isClear, isOnTable"); "" when there are none.
std::string lost_names(const MapSummary& s, schema::GeneratorKind kind);

/// For a step carried out by its generated action (StepTransfer::Kind::Generated), one line
/// per part of the target match whose tuple starts at a part of the source match:
/// `E ↦ BreadSliced E because hasColor(E) == "purple" and BreadSliced ⇒ {...}`, the source part
/// (in x, the state before the step) and the target part (in y) called by transfer::part_word,
/// the reason being the source state's statements the target object's query asks for and the
/// map's line for that object. Empty for any other step.
std::vector<std::string> binding_reasons(const migrate::SchemaMap& f,
                                         const rewrite::Rule& source_rule,
                                         const rewrite::Rule& target_rule,
                                         const transfer::StepTransfer& step, const acset::ACSet& x,
                                         const acset::ACSet& y);

/// What a step deletes, creates and keeps of what its match binds, as parts of the pictures of
/// its states (CSS classes "deleted", "created" and "matched").
struct StepMarks {
    std::vector<dot::PartClass> source_before, source_after, target_before, target_after;
};

/// The parts of L outside l(K) through the match (in the state before, "deleted") and of R
/// outside r(K) through the comatch (in the state after, "created"), and the kept parts through
/// both ("matched"), on each side; a side whose rule is null, or the target side of a step not
/// carried out by its generated action, is left unmarked.
StepMarks step_marks(const rewrite::Rule* source_rule, const rewrite::Rule* target_rule,
                     const transfer::StepTransfer& step);

/// An object of a state whose parts all have the same attribute values (the constants a map
/// gives, `breadSlicedHasMass = 0.0`), said once instead of on every part.
struct UniformValues {
    ObId ob;
    std::vector<std::string> values; // `hasMass = 0.0`, in schema order
};

/// The objects of x with parts and attributes whose every attribute has one and the same
/// concrete value on all its parts.
std::vector<UniformValues> uniform_values(const acset::ACSet& x);

/// Labels for the parts of x whose only word is a label or a name catplan made up (`block@4`):
/// their term when another part reaches them (`isEmpty(empty)`), else their object (`a
/// Receptacle`), so that a picture shows no made-up name.
std::vector<dot::PartLabel> readable_labels(const acset::ACSet& x);

} // namespace catplan::report
