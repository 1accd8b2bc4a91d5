// Imports (docs/language.md, "Files and imports"): `@import "path.cp"` loads a file relative to the
// importing one, each file once, and reports a cycle with its chain of files; a `.pddl` file is
// read by pddl_imports.cpp.

#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"

#include <filesystem>
#include <fmt/format.h>

namespace catplan::lang::detail {
namespace {

void import(Elaborator& ctx, const MacroCall& form, std::uint32_t file) {
    if (form.header.size() == 1 && form.header[0].kind == Expr::Kind::Name &&
        form.header[0].text == "catlab" && !form.has_body && form.assigned.empty()) {
        import_catlab(ctx);
        return;
    }
    if (form.header.size() != 1 || form.header[0].kind != Expr::Kind::String || form.has_body ||
        !form.assigned.empty()) {
        ctx.sink.error(form.range, "expected @import \"path/to/file.cp\"");
        return;
    }
    const Expr& arg = form.header[0];
    std::filesystem::path base = std::filesystem::path(ctx.sources.name(file)).parent_path();
    std::string path = (base / arg.text).lexically_normal().string();
    std::string key = canonical_path(path);
    const auto& stack = ctx.import_stack;
    for (std::size_t i = 0; i < stack.size(); ++i) {
        if (stack[i] == key) {
            std::string chain;
            for (std::size_t j = i; j < stack.size(); ++j) {
                chain += std::filesystem::path(stack[j]).filename().string() + " -> ";
            }
            ctx.sink.error(arg.range, fmt::format("import cycle: {}{}", chain,
                                                  std::filesystem::path(key).filename().string()));
            return;
        }
    }
    if (ctx.loaded.count(key)) {
        return; // already loaded through another import
    }
    auto imported = ctx.sources.add_file(path);
    if (!imported) {
        ctx.sink.error(arg.range, fmt::format("cannot read imported file '{}'", path));
        return;
    }
    if (is_pddl_path(path)) {
        ctx.loaded.insert(key);
        import_pddl_file(ctx, *imported, arg.range, true);
        return;
    }
    load_buffer(ctx, *imported, key, true);
}

} // namespace

std::string canonical_path(const std::string& path) {
    std::error_code ec;
    auto p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : p.string();
}

void load_buffer(Elaborator& ctx, std::uint32_t file, const std::string& key, bool imported) {
    ctx.import_stack.push_back(key);
    ctx.loaded.insert(key);
    ParsedFile parsed = parse(ctx.sources, file, ctx.sink);
    if (parsed.catlab_using.valid()) {
        import_catlab(ctx); // pasted `using Catlab`: Catlab's schemas are in scope, as in Julia
    }
    for (const auto& form : parsed.forms) {
        if (form.name == "import") {
            import(ctx, form, file);
        }
    }
    elaborate_file(ctx, parsed, imported);
    ctx.import_stack.pop_back();
}

} // namespace catplan::lang::detail
