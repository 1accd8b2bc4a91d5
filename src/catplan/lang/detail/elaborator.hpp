#pragma once
// What every part of elaboration shares: the diagnostics sink, the module being built, the names
// declared so far, and the lookups each part needs. One Elaborator lives for one load_file or
// load_source call; each file of lang/ elaborates one kind of declaration into it:
//
//   module.cpp           the order of a file's passes (schemas, kinds, instances, rules, ...)
//   imports.cpp          @import, import cycles, loading each file once
//   pddl_imports.cpp     @import of a .pddl file; names, implied entries and the actions
//                        section of maps over PDDL schemas
//   schemas.cpp          @present -> Schema
//   kinds.cpp            value kinds of attribute types inferred from literals
//   instances.cpp        @acset_colim (a presentation, detail/colimit.hpp) and @acset -> ACSet
//   rules.cpp            @rule, @migration as a rule -> rewrite::Rule (rule_expressions.cpp: the
//                        attribute expressions of its effect)
//   domains.cpp          @domain -> plan::Domain, @problem -> plan::Problem
//   map_declarations.cpp @migration Name(Target, Source), @compose, @migrate (maps.cpp: the
//                        entries of a map)

#include "catplan/acset/value.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/schema/schema.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace catplan::lang::detail {

/// The kind an attribute type took from a literal, and the literal (for "inferred here" notes).
struct InferredKind {
    schema::ValueKind kind;
    SourceRange range;
    /// The attribute type's schema is declared in the file being elaborated.
    bool local;
};

/// The kinds inferred on one schema, by attribute type index.
using InferredKinds = std::map<std::uint32_t, InferredKind>;

/// The state of one load: what is declared so far and where diagnostics go.
struct Elaborator {
    Elaborator(SourceManager& source_manager, DiagnosticSink& diagnostics,
               const LoadOptions& load_options)
        : sources(source_manager), sink(diagnostics), options(load_options) {}

    /// Claims a name for the whole module (all files); a name taken already is a warning, and
    /// the earlier declaration is dropped (the later one wins, as Julia rebinds names).
    bool claim_name(const std::string& name, SourceRange range);
    /// The schema a name refers to (`yName` too when allow_yoneda), or nullptr after an error.
    std::shared_ptr<schema::Schema> lookup_schema(const Expr& name, bool allow_yoneda);
    /// The kinds inferred on this schema so far, or nullptr.
    const InferredKinds* inferred_kinds(const schema::Schema& s) const;

    SourceManager& sources;
    DiagnosticSink& sink;
    LoadOptions options;
    Module module;

    /// Imports: the files being loaded (innermost last) and every file loaded, by canonical path.
    std::vector<std::string> import_stack;
    std::set<std::string> loaded;

    std::unordered_map<std::string, SourceRange> names;
    std::unordered_map<std::string, std::shared_ptr<schema::Schema>> schemas;
    /// The schemas of the file being elaborated (their kinds may still be inferred).
    std::set<const schema::Schema*> local_schemas;
    /// Schemas with errors: visible so that their instances are checked, never in the module.
    std::set<const schema::Schema*> broken;
    /// The instance names of the file being elaborated (so "not a schema" can say so early).
    std::set<std::string> file_instances;
    /// Kinds inferred from literals, per schema (applied to the schema after each file's pass).
    std::map<schema::Schema*, InferredKinds, std::less<>> inferred;
    /// The PDDL domains imported so far, by their PDDL name (pddl_imports.cpp).
    std::map<std::string, std::shared_ptr<const pddl::Import>> pddl_domains;
};

/// A declaration with its kind, name, place and schema; the caller fills in the rest.
Declaration new_declaration(DeclKind kind, std::string name, SourceRange range, bool imported,
                            schema::SchemaPtr schema);

/// Whether the expression is an Int, Float, String (or Julia :symbol) or Bool literal.
bool is_literal(const Expr& e);
/// The kind of a literal (Unknown for anything else).
schema::ValueKind literal_kind(const Expr& e);
/// The names on the left of `x::T` or `(x, y)::T`; anything else is reported.
std::vector<const Expr*> declared_names(const Expr& lhs, DiagnosticSink& sink);
/// Whether the call has n arguments; reports it otherwise.
bool check_arity(const Expr& call, std::size_t n, DiagnosticSink& sink);
/// The literal as a value of attribute type t, or a located error naming both kinds (with a note
/// on the literal the type's kind was inferred from, when `inferred` has it).
std::optional<acset::Value> literal_value(const schema::Schema& s, AttrTypeId t, const Expr& lit,
                                          const InferredKinds* inferred, DiagnosticSink& sink);

} // namespace catplan::lang::detail
