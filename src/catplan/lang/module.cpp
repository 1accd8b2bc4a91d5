// The front door of the language (module.hpp): load_file and load_source, and the order in which
// the parts of a file are elaborated (detail/elaboration.hpp).

#include "catplan/lang/module.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/syntax.hpp"

#include <fmt/format.h>
#include <vector>

namespace catplan::lang {

const Declaration* Module::find(std::string_view name) const {
    for (const auto& d : decls_) {
        if (d.name == name) {
            return &d;
        }
    }
    return nullptr;
}

void Module::remove(std::string_view name) {
    std::erase_if(decls_, [&](const Declaration& d) { return d.name == name; });
}

void Module::add(Declaration d) {
    CATPLAN_ASSERT(find(d.name) == nullptr, "duplicate declaration name");
    decls_.push_back(std::move(d));
}

namespace detail {
namespace {

// A file's forms other than schemas and imports, by the pass that elaborates them.
struct FileForms {
    std::vector<const MacroCall*> instances, rules, domains, problems, maps, one_argument_maps,
        composites, migrations;
};

// Elaborates the file's schemas, in order, and sorts its other forms; reports unknown macros.
FileForms schemas_and_forms(Elaborator& ctx, const ParsedFile& parsed, bool imported) {
    FileForms f;
    for (const auto& form : parsed.forms) {
        if (form.name == "import") {
            continue;
        }
        if (form.name == "present") {
            elaborate_schema(ctx, form, imported);
        } else if (form.name == "acset_type" || form.name == "abstract_acset_type") {
            elaborate_acset_type(ctx, form);
        } else if (form.name == "acset_colim" || form.name == "acset") {
            f.instances.push_back(&form);
        } else if (form.name == "migration" && is_map_form(form)) {
            f.maps.push_back(&form);
        } else if (is_one_argument_map(form)) {
            f.one_argument_maps.push_back(&form);
        } else if (form.name == "rule" || form.name == "migration") {
            f.rules.push_back(&form);
        } else if (form.name == "compose") {
            f.composites.push_back(&form);
        } else if (form.name == "migrate") {
            f.migrations.push_back(&form);
        } else if (form.name == "domain") {
            f.domains.push_back(&form);
        } else if (form.name == "problem") {
            f.problems.push_back(&form);
        } else {
            ctx.sink.error(form.name_range,
                           fmt::format("unknown macro '@{}' (expected @present, @acset_type, "
                                       "@acset_colim, @acset, @rule, @migration, @compose, "
                                       "@migrate, @domain, @problem or @import)",
                                       form.name));
        }
    }
    return f;
}

} // namespace

void elaborate_file(Elaborator& ctx, const ParsedFile& parsed, bool imported) {
    // Schemas first, then kinds are inferred from every literal of the file, then instances:
    // so the order of declarations in a file does not change the meaning.
    FileForms f = schemas_and_forms(ctx, parsed, imported);
    std::vector<InstanceForm> instances = instance_headers(ctx, f.instances);
    infer_kinds(ctx, instances, f.rules, f.domains);
    elaborate_instances(ctx, instances, imported);
    // Rules, domains and problems refer to schemas, instances and rules declared above.
    for (const auto* form : f.rules) {
        elaborate_top_rule(ctx, *form, imported);
    }
    for (const auto* form : f.domains) {
        elaborate_domain(ctx, *form, imported);
    }
    for (const auto* form : f.problems) {
        elaborate_problem(ctx, *form, imported);
    }
    // Maps refer to schemas only; composites to maps.
    for (const auto* form : f.maps) {
        elaborate_map_declaration(ctx, *form, imported);
    }
    for (const auto* form : f.one_argument_maps) {
        elaborate_one_argument_map(ctx, *form, imported);
    }
    for (const auto* form : f.composites) {
        elaborate_compose(ctx, *form, imported);
    }
    // Migrated instances refer to instances above and make instances.
    for (const auto* form : f.migrations) {
        elaborate_migrate(ctx, *form, imported);
    }
    ctx.local_schemas.clear();
}

} // namespace detail

Module load_file(const std::string& path, SourceManager& sources, DiagnosticSink& sink,
                 const LoadOptions& options) {
    detail::Elaborator ctx(sources, sink, options);
    auto file = sources.add_file(path);
    if (!file) {
        sink.error(fmt::format("cannot read file '{}'", path));
        return {};
    }
    if (detail::is_pddl_path(path)) {
        // A PDDL file read alone (`catplan check domain.pddl`): its declarations are its own, as
        // when a .cp file imports it; a problem needs its domain imported before it.
        ctx.loaded.insert(detail::canonical_path(path));
        detail::import_pddl_file(ctx, *file, SourceRange{}, false);
        return std::move(ctx.module);
    }
    detail::load_buffer(ctx, *file, detail::canonical_path(path), false);
    return std::move(ctx.module);
}

Module load_source(std::string name, std::string text, SourceManager& sources, DiagnosticSink& sink,
                   const LoadOptions& options) {
    detail::Elaborator ctx(sources, sink, options);
    std::uint32_t file = sources.add_buffer(std::move(name), std::move(text));
    detail::load_buffer(ctx, file, detail::canonical_path(std::string(sources.name(file))), false);
    return std::move(ctx.module);
}

} // namespace catplan::lang
