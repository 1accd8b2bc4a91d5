#pragma once
// The text language's front door: load a .cp file (and its @imports) into a Module of named
// declarations, each elaborated into core objects (schemas, states). docs/language.md describes
// the language; this layer's concepts are:
//
//   syntax.hpp   tokens and a generic AST of macro calls (no meaning attached)
//   module.hpp   elaboration per macro: @present -> Schema, @acset_colim / @acset -> ACSet,
//                @rule / @migration -> rewrite::Rule, @domain -> plan::Domain,
//                @problem -> plan::Problem, @migration Name(Target, Source) and @compose ->
//                migrate::SchemaMap (an ontology map), @import -> more declarations (of a
//                .pddl file: its domain, whose schema is named like it, or its problem);
//                printing back to loadable text
//
// Rule blocks (Pre/Keep/Eff, or L/K/R) are *partial* presentations, unlike instances: a hom or
// attribute a block never mentions stays unset, meaning "no constraint" in Pre, "rewritten by
// Eff" in Keep and "unchanged" for a kept part in Eff (docs/language.md, "Rules").
//
//   SourceManager sources;
//   DiagnosticSink sink(sources);
//   Module m = load_file("examples/colorblocksworld/colorblocksworld.cp", sources, sink);
//   if (sink.has_errors()) std::cerr << sink.render();
//   const Declaration* initial = m.find("Initial");   // initial->instance is the state

#include "catplan/acset/acset.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/result.hpp"
#include "catplan/base/source.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/rewrite/rule.hpp"
#include "catplan/schema/schema.hpp"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::lang {

enum class DeclKind { Schema, Instance, Rule, Domain, Problem, Map };

/// An entry of a map's `actions` section (`unstack => pick-from`): steps of the source action
/// become steps of the target action.
struct ActionCorrespondence {
    std::string source, target;
    SourceRange range;
};

/// An entry of a map's `functions` section (`travel-time => road-length`): the target's function
/// takes the source problem's values of the source's function, at the same objects.
struct FunctionCorrespondence {
    std::string target, source;
    SourceRange range;
};

/// A map's sections beyond its entries, between PDDL domains.
struct MapSections {
    std::vector<ActionCorrespondence> actions;
    std::vector<FunctionCorrespondence> functions;
};

struct Declaration {
    DeclKind kind = DeclKind::Schema;
    std::string name;
    SourceRange range;
    /// True when the declaration comes from an @import-ed file rather than the loaded one.
    bool imported = false;
    /// The schema (for an instance, rule, domain or problem: the schema it is on; for a map
    /// F : D' -> D, its target D', the schema of the states it produces).
    schema::SchemaPtr schema;
    /// Instances only.
    std::shared_ptr<const acset::ACSet> instance;
    /// Rules only (top-level rules; rules written inside a domain live in the domain).
    rewrite::RulePtr rule;
    /// Domains only.
    plan::DomainPtr domain;
    /// Problems only; also the names of its initial and goal instances.
    plan::ProblemPtr problem;
    std::string initial_name, goal_name;
    /// Maps only: the finished, valid ontology map (map->target() is D', map->source() is D).
    std::shared_ptr<const migrate::SchemaMap> map;
    /// Maps only: the actions and functions sections, in the order written.
    std::vector<ActionCorrespondence> actions;
    std::vector<FunctionCorrespondence> functions;
    /// Domains and problems read from a PDDL file (`@import "x.pddl"`): the import, with the
    /// PDDL names of the schema's generators and the rules' actions.
    std::shared_ptr<const pddl::Import> pddl;
};

class Module {
public:
    /// Every declaration that elaborated without error, in load order, imports first.
    const std::vector<Declaration>& declarations() const { return decls_; }

    /// The declaration with this name, or nullptr.
    const Declaration* find(std::string_view name) const;
    /// Appends a declaration; its name must be new (asserted: the loader reports duplicates).
    void add(Declaration d);
    /// Drops the declaration with this name, if any (a later declaration replaces it).
    void remove(std::string_view name);

private:
    std::vector<Declaration> decls_;
};

/// Limits that keep elaboration finite on cyclic schemas.
struct LoadOptions {
    /// A free instance that needs more new (unnamed) parts than this is reported as infinite.
    std::size_t max_fresh_parts = 100000;
    /// The most parts and variables an @acset may declare in all (docs/language.md, "States as
    /// tables"): far beyond any planning state, and checked before anything is allocated.
    std::uint64_t max_table_parts = 10'000'000;
};

/// Parses and elaborates a file and its imports (a `.pddl` file: the domain it declares, as an
/// import of it would); every error goes to `sink`; the module holds what succeeded.
Module load_file(const std::string& path, SourceManager& sources, DiagnosticSink& sink,
                 const LoadOptions& options = {});
/// Like load_file for text in memory; `name` is the display name and anchors relative imports.
Module load_source(std::string name, std::string text, SourceManager& sources, DiagnosticSink& sink,
                   const LoadOptions& options = {});

/// One line: "schema Kitchenworld: 10 objects, 13 homs, 3 attribute types, 15 attributes" /
/// "instance Initial (ColorBlocksworld): 11 parts (Block 7, Empty 1, Gripper 1, On 2), 3
/// variables" / "rule unstack(block, underblock) on ColorBlocksworld: L 9 parts, K 3, R 5,
/// deletes 4, creates 1, 1 NAC" / "domain Blocksworld (ColorBlocksworld): 4 rules: unstack,
/// stack, pickup, putdown" / "problem CaseStudy (Blocksworld): initial Initial, goal Goal" /
/// "map ColorToKitchen : KitchenWorld -> ColorBlocksworld (conjunctive, 10 objects, 5 by query,
/// 13 homs, 3 attribute types, 15 attributes)".
std::string summarize(const Declaration& d);

/// The one-line summary of a rule (as for a rule declaration), e.g. for the rules of a domain.
std::string summarize_rule(const rewrite::Rule& rule);

/// The schema in @present form, loadable again to an equal schema.
std::string print_schema(const schema::Schema& s);
/// The state in @acset_colim form on its schema's name, loadable again to an equal state (==)
/// with the same names for names that are identifiers; unnamed parts and variables get
/// generated names (`_Block3`), and a name that two parts share is kept by the first (the parts
/// of the objects `name_first`, in that order, then the others) and becomes `a_Block` for the
/// others. Unset cells cannot be written and are listed as comments.
std::string print_instance(const acset::ACSet& x, std::string_view name,
                           std::span<const ObId> name_first = {});
/// The name printers give the part `index` (0-based) of `kind` when the name it wants is taken
/// or cannot be written: `a_Block` for a wanted `a`, `_Block3` for none.
std::string generated_name(std::string_view wanted, std::string_view kind, std::uint32_t index);
/// The rule as a domain's `@rule name(params) begin ... end`, loadable again (inside a domain on
/// its schema) to the same rule up to the order of parts; or why the language cannot write it.
Result<std::string> print_rule(const rewrite::Rule& rule);
/// The domain as `@domain Name(Schema) begin ... end` with its facts and rules (print_rule), or
/// why it cannot be written.
Result<std::string> print_domain(const plan::Domain& d);
/// `@problem Name(domain) begin initial = ...; goal = ... end` naming the instances printed as
/// `initial` and `goal` (the goal by print_instance with `name_first`), with a `NAC => begin ...
/// end` block per negative goal condition (`PAC` for a positive one); or why it cannot be
/// written.
Result<std::string> print_problem(const plan::Problem& p, std::string_view domain,
                                  std::string_view initial, std::string_view goal,
                                  std::span<const ObId> name_first = {});

} // namespace catplan::lang
