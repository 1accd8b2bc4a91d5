#pragma once
// Elaboration of an ontology map's entries (`@migration Name(Target, Source) begin ... end`) into a
// migrate::SchemaMap. map_declarations.cpp resolves the header and the name; this file gives
// each entry its meaning and turns every problem of the map into a located diagnostic.

#include "catplan/base/diagnostic.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/migrate/schema_map.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace catplan::lang::detail {

/// A map as written: its name, its target D' and source D, and its entries.
struct MapForm {
    std::string name;
    SourceRange name_range;
    schema::SchemaPtr target;
    schema::SchemaPtr source;
    const std::vector<Expr>* body = nullptr;
    /// Called before the map is finished, with whether each target generator has an entry: adds
    /// the entries the schemas imply (PDDL's is-a homs, argument homs and names). Optional.
    std::function<void(migrate::SchemaMap&, const std::function<bool(schema::Generator)>&)>
        complete;
    /// A statement of the body that is not an entry (an actions section): true when it handled
    /// it. Optional.
    std::function<bool(const Expr&)> other_statement;
};

/// The finished map, or nullptr when it has errors (all of them reported to `sink`, warnings too).
std::shared_ptr<const migrate::SchemaMap> elaborate_map(const MapForm& form, DiagnosticSink& sink);

} // namespace catplan::lang::detail
