#pragma once
// Catlab's ACSet JSON (ACSets.jl `JSONACSets`), for states and for schemas, both directions.
//
// A state is one JSON object: a key per object of the schema (schema order) holding one row per
// part, then a key per attribute type holding one {"_id": j} per attribute variable. A row is
// "_id" (1-based), then the object's homs (1-based target ids, 0 when unset), then its attributes
// (a JSON value, {"_var": j} for variable j, null when unset):
//
//   {"V":[{"_id":1},{"_id":2}],"E":[{"_id":1,"src":1,"tgt":2}]}
//
// A schema is {"version": ..., "Ob": [{"name"}], "Hom": [{"name","dom","codom"}], "AttrType":
// [{"name","kind"}], "Attr": [{"name","dom","codom"}], "equations": [{"dom","codom","name",
// "paths"}]}.
//
// What Catlab's format lacks, catplan carries in keys ACSets.jl can live with:
// - the value kind of an attribute type, as "kind" ("Bool", "Int", "Float", "String") in its
//   "AttrType" entry: ACSets.jl's schema reader reads only "name" there;
// - the name of a part or variable, as "_name" in its row, written only on request (`names`):
//   ACSets.jl's instance reader sets every key of a row other than "_id" as a subpart, so a file
//   meant for Julia is written without them.
// Reading a state infers the kind of an Unknown attribute type from its values (see read_acset).
// Reading accepts what older Catlab wrote: rows without "_id" (and `{}` for a variable), and a
// missing table, which has no rows (as ACSets.jl reads it). A state that breaks one of the
// schema's path equations is rejected, at the row that breaks it.
//
// Readers report every problem as a located Diagnostic (the text must be registered in the
// SourceManager): syntax, nesting deeper than kMaxNesting (256) arrays and objects, numbers out of
// range, duplicate keys, and what does not fit the schema. Writers cannot fail: every JSON text
// catplan writes goes through `dump`, which turns invalid UTF-8 into U+FFFD instead of throwing.
//
//   SourceManager sources;
//   DiagnosticSink sink(sources);
//   auto file = sources.add_buffer("g.json", text);
//   if (auto g = json::read_acset(graph_schema, file, sources, sink)) { ... json::write_acset(*g) }

#include "catplan/acset/acset.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"
#include "catplan/schema/schema.hpp"

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace catplan::json {

/// The text of a JSON document, indented by `indent` spaces (compact when negative); never throws:
/// a string holding invalid UTF-8 is written with U+FFFD in place of the bad bytes.
std::string dump(const nlohmann::json& doc, int indent = -1);
/// The same for a document that keeps its keys in insertion order.
std::string dump(const nlohmann::ordered_json& doc, int indent = -1);

/// Catlab ACSet JSON of a state (compact unless pretty); floats in shortest round-trip form,
/// non-finite floats as null; with `names`, each named part and variable gets a "_name" key.
std::string write_acset(const acset::ACSet& x, bool pretty = false, bool names = false);

/// Catlab schema JSON, with the kind of each attribute type that has one as a "kind" key.
std::string write_schema(const schema::Schema& s, bool pretty = false);

/// Reads a state on `schema` from JSON text registered as file `file` in `sources`; nullopt on
/// errors (all reported to sink). An attribute type of kind Unknown takes the kind of its first
/// concrete value (Int widened to Float when a float appears too); the returned state is then on
/// an adjusted copy of the schema. JSON integers are accepted for Float attributes.
std::optional<acset::ACSet> read_acset(const schema::SchemaPtr& schema, std::uint32_t file,
                                       const SourceManager& sources, DiagnosticSink& sink);

/// Reads a schema (named `name`) from JSON text registered as `file`; nullptr on errors (all
/// reported to sink). Accepts the older "domain"/"codomain" keys and a missing "equations".
schema::SchemaPtr read_schema(std::string name, std::uint32_t file, const SourceManager& sources,
                              DiagnosticSink& sink);

/// Whether JSON text looks like a schema (has "Ob" and "Hom" arrays) rather than an instance.
bool looks_like_schema(std::string_view text);

} // namespace catplan::json
