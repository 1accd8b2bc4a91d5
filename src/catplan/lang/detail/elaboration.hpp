#pragma once
// The passes of elaboration, one file each (the list is in detail/elaborator.hpp). module.cpp runs
// them on each file in this order: schemas, instance headers, kinds, instances, rules, domains,
// problems, maps, composites, migrated instances; so a file's meaning does not depend on the order
// of its declarations.

#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/detail/map_elaboration.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/schema/schema.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::lang::detail {

// ---- module.cpp, imports.cpp
// ---------------------------------------------------------------------

/// Elaborates the forms of one parsed file (its imports are loaded already).
void elaborate_file(Elaborator& ctx, const ParsedFile& parsed, bool imported);
/// The path as a key that is the same for every spelling of one file.
std::string canonical_path(const std::string& path);
/// Parses a loaded buffer, loads its imports, and elaborates it.
void load_buffer(Elaborator& ctx, std::uint32_t file, const std::string& key, bool imported);

// ---- pddl_imports.cpp
// ----------------------------------------------------------------------------

/// Whether an imported path names a PDDL file (it ends in .pddl).
bool is_pddl_path(std::string_view path);
/// Declares a loaded PDDL file: a domain (its schema and domain named as the file's `(domain
/// ...)`) or a problem of a domain imported before; errors at `at` (none: the file's first form)
/// or in the file.
void import_pddl_file(Elaborator& ctx, std::uint32_t file, SourceRange at, bool imported);
/// Rewrites names spelled with hyphens (`courier-in`, which parses as a subtraction) into names,
/// where they name a generator or action of an imported PDDL domain.
void spell_pddl_names(const Elaborator& ctx, MacroCall& form);
/// Gives a map over PDDL schemas the entries PDDL's structure implies and reads its actions and
/// functions sections into `sections`.
void add_pddl_hooks(const Elaborator& ctx, MapForm& form, MapSections& sections);

// ---- catlab.cpp
// ----------------------------------------------------------------------------------

/// Loads Catlab's standard schemas (once per load), for `@import catlab` and `using Catlab`.
void import_catlab(Elaborator& ctx);
/// The library's text (for tests and docs).
std::string_view catlab_library_text();
/// `@acset_type Name(Schema, ...)`: Name becomes another name of the schema.
void elaborate_acset_type(Elaborator& ctx, const MacroCall& form);
/// Whether a form is DataMigrations' `M = @migration Source begin ... end`, a map whose target
/// schema its entries declare (`V => V`, `(src: E → V) => tgt`), rather than a rule.
bool is_one_argument_map(const MacroCall& form);
/// Declares such a map; its target schema is named `M_domain`.
void elaborate_one_argument_map(Elaborator& ctx, const MacroCall& form, bool imported);

// ---- schemas.cpp
// ---------------------------------------------------------------------------------

/// `@present Name(FreeSchema) begin ... end` or `@present Name <: Base begin ... end`.
void elaborate_schema(Elaborator& ctx, const MacroCall& form, bool imported);

// ---- instances.cpp, kinds.cpp
// --------------------------------------------------------------------

/// An instance form with its name and schema resolved.
struct InstanceForm {
    const MacroCall* form;
    std::string name;
    SourceRange name_range;
    std::shared_ptr<schema::Schema> schema;
};

/// The file's instance forms whose headers resolve (the others are reported); records their
/// names as the file's instances.
std::vector<InstanceForm> instance_headers(Elaborator& ctx,
                                           const std::vector<const MacroCall*>& forms);
/// Infers value kinds from the literals of the file's instances, rules and domains and gives
/// them to the attribute types of the file's own schemas that declare none.
void infer_kinds(Elaborator& ctx, const std::vector<InstanceForm>& instances,
                 const std::vector<const MacroCall*>& rules,
                 const std::vector<const MacroCall*>& domains);
/// Builds each instance (@acset_colim or @acset) and declares those without errors.
void elaborate_instances(Elaborator& ctx, const std::vector<InstanceForm>& instances,
                         bool imported);

// ---- rules.cpp, domains.cpp
// ----------------------------------------------------------------------

/// A top-level `@rule` or rule-form `@migration`.
void elaborate_top_rule(Elaborator& ctx, const MacroCall& form, bool imported);
/// `@domain Name(Schema) begin rules... end`.
void elaborate_domain(Elaborator& ctx, const MacroCall& form, bool imported);
/// `@problem Name(Domain) begin initial = I; goal = G end`.
void elaborate_problem(Elaborator& ctx, const MacroCall& form, bool imported);

// ---- map_declarations.cpp
// ------------------------------------------------------------------------

/// Whether a `@migration` form is an ontology map rather than a rule: `@migration Name(Target,
/// Source)` or `Name = @migration Target Source` (a rule names SchRule or one schema).
bool is_map_form(const MacroCall& form);
/// `@migration Name(Target, Source) begin ... end`.
void elaborate_map_declaration(Elaborator& ctx, const MacroCall& form, bool imported);
/// `@compose H(F, G)`: H = F ∘ G as functors, so Δ_H migrates along F, then along G.
void elaborate_compose(Elaborator& ctx, const MacroCall& form, bool imported);
/// `Name = @migrate Target X begin ... end`: the instance X migrated along the map the body
/// gives.
void elaborate_migrate(Elaborator& ctx, const MacroCall& form, bool imported);

} // namespace catplan::lang::detail
