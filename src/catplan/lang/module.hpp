#pragma once
// The text language's front door: load a .cp file (and its @imports) into a Module of named
// declarations, each elaborated into core objects (schemas, states). docs/language.md describes
// the language; this layer's concepts are:
//
//   syntax.hpp   tokens and a generic AST of macro calls (no meaning attached)
//   module.hpp   elaboration per macro: @present -> Schema, @acset_colim / @acset -> ACSet,
//                @import -> more declarations; printing back to loadable text
//
//   SourceManager sources;
//   DiagnosticSink sink(sources);
//   Module m = load_file("examples/colorblocksworld/colorblocksworld.cp", sources, sink);
//   if (sink.has_errors()) std::cerr << sink.render();
//   const Declaration* initial = m.find("Initial");   // initial->instance is the state

#include "catplan/acset/acset.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"
#include "catplan/schema/schema.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace catplan::lang {

enum class DeclKind { Schema, Instance };

struct Declaration {
    DeclKind kind = DeclKind::Schema;
    std::string name;
    SourceRange range;
    /// True when the declaration comes from an @import-ed file rather than the loaded one.
    bool imported = false;
    /// The schema (for an instance: its schema).
    schema::SchemaPtr schema;
    /// Instances only.
    std::shared_ptr<const acset::ACSet> instance;
};

class Module {
public:
    /// Every declaration that elaborated without error, in load order, imports first.
    const std::vector<Declaration>& declarations() const { return decls_; }

    /// The declaration with this name, or nullptr.
    const Declaration* find(std::string_view name) const;
    /// Appends a declaration; its name must be new (asserted: the loader reports duplicates).
    void add(Declaration d);

private:
    std::vector<Declaration> decls_;
};

/// Limits that keep elaboration finite on cyclic schemas.
struct LoadOptions {
    /// A free instance that needs more new (unnamed) parts than this is reported as infinite.
    std::size_t max_fresh_parts = 100000;
};

/// Parses and elaborates a file and its imports; every error goes to `sink`; the module holds
/// what succeeded.
Module load_file(const std::string& path, SourceManager& sources, DiagnosticSink& sink,
                 const LoadOptions& options = {});
/// Like load_file for text in memory; `name` is the display name and anchors relative imports.
Module load_source(std::string name, std::string text, SourceManager& sources, DiagnosticSink& sink,
                   const LoadOptions& options = {});

/// One line: "schema Kitchenworld: 10 objects, 13 homs, 3 attribute types, 15 attributes" /
/// "instance Initial (ColorBlocksworld): 11 parts (Block 7, Empty 1, Gripper 1, On 2), 3
/// variables".
std::string summarize(const Declaration& d);

/// The schema in @present form, loadable again to an equal schema.
std::string print_schema(const schema::Schema& s);
/// The state in @acset_colim form on its schema's name, loadable again to an equal state (==)
/// with the same names for names that are identifiers; unnamed parts and variables get
/// generated names (`_Block3`). Unset cells cannot be written and are listed as comments.
std::string print_instance(const acset::ACSet& x, std::string_view name);

} // namespace catplan::lang
