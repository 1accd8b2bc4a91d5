// PDDL in the language (docs/language.md, "PDDL files"): `@import "x.pddl"` declares a PDDL
// domain (its schema and its domain both named as the file's `(domain ...)` is) or a problem of
// an imported domain; a map over PDDL schemas may spell names with hyphens (`courier-in`), gets
// the entries that PDDL's structure implies (is-a homs, argument homs, object names), and may
// name the target action of source actions in an `actions` section and the source function whose
// values a target function takes in a `functions` section.

#include "catplan/base/ascii.hpp"
#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/detail/map_elaboration.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/pddl.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <set>

namespace catplan::lang::detail {
namespace {

using migrate::Query;
using migrate::SchemaMap;
using migrate::Term;
using schema::Generator;
using schema::GeneratorKind;
using schema::Schema;

/// The position of the first character of text at or after i that is not blank or in a comment.
std::size_t skip_blanks(std::string_view text, std::size_t i) {
    while (i < text.size()) {
        if (std::isspace(static_cast<unsigned char>(text[i]))) {
            ++i;
        } else if (text[i] == ';') {
            while (i < text.size() && text[i] != '\n') {
                ++i;
            }
        } else {
            break;
        }
    }
    return i;
}

/// "domain" or "problem": the word after `(define (`, lower-cased ("" if there is none).
std::string pddl_kind(std::string_view text) {
    std::size_t i = 0;
    auto skip = [&] { i = skip_blanks(text, i); };
    auto word = [&] {
        skip();
        std::string w;
        while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) ||
                                   text[i] == '-' || text[i] == '_')) {
            w += ascii_lower(text[i++]);
        }
        return w;
    };
    auto open = [&] {
        skip();
        return i < text.size() && text[i++] == '(';
    };
    if (!open() || word() != "define" || !open()) {
        return "";
    }
    return word();
}

/// The name after `(:domain` in a problem's text, lower-cased ("" if there is none).
std::string problem_domain(std::string_view text) {
    std::string lowered = ascii_lowercase(text);
    std::size_t i = lowered.find("(:domain");
    if (i == std::string::npos) {
        return "";
    }
    i += 8;
    while (i < lowered.size() && std::isspace(static_cast<unsigned char>(lowered[i]))) {
        ++i;
    }
    std::size_t b = i;
    while (i < lowered.size() && !std::isspace(static_cast<unsigned char>(lowered[i])) &&
           lowered[i] != ')') {
        ++i;
    }
    return lowered.substr(b, i - b);
}

void declare_domain(Elaborator& ctx, std::uint32_t file, bool imported) {
    auto d = pddl::parse_domain(file, ctx.sources, ctx.sink);
    if (!d) {
        return;
    }
    auto im = pddl::import_pddl(*d, nullptr, ctx.sink);
    if (!im || !ctx.claim_name(d->name, d->range)) {
        return;
    }
    auto shared = std::make_shared<const pddl::Import>(std::move(*im));
    // The elaborator's table holds mutable schemas (it fills in inferred kinds of local ones);
    // an imported schema is never local, so it is never changed.
    ctx.schemas[d->name] = std::const_pointer_cast<Schema>(shared->domain->schema);
    ctx.pddl_domains[d->name] = shared;
    Declaration decl =
        new_declaration(DeclKind::Domain, d->name, d->range, imported, shared->domain->schema);
    decl.domain = shared->domain;
    decl.pddl = shared;
    ctx.module.add(std::move(decl));
}

void declare_problem(Elaborator& ctx, std::uint32_t file, SourceRange at, bool imported) {
    // The problem names its domain; the domain must be imported first.
    std::string domain_name = problem_domain(ctx.sources.text(file));
    if (ctx.pddl_domains.count(domain_name) == 0) {
        ctx.sink.error(at, fmt::format("the PDDL problem is for the domain '{}', which is not "
                                       "imported: import its .pddl file first",
                                       domain_name));
        return;
    }
    const auto& domain = ctx.pddl_domains.at(domain_name);
    auto p = pddl::parse_problem(file, domain->pddl_domain, ctx.sources, ctx.sink);
    if (!p) {
        return;
    }
    auto im = pddl::import_problem(*domain, *p, ctx.sink);
    if (!im || !ctx.claim_name(p->name, p->range)) {
        return;
    }
    auto shared = std::make_shared<const pddl::Import>(std::move(*im));
    Declaration decl =
        new_declaration(DeclKind::Problem, p->name, p->range, imported, shared->domain->schema);
    decl.problem = shared->problem;
    decl.pddl = shared;
    ctx.module.add(std::move(decl));
}

// ---- names spelled with hyphens -----------------------------------------------------------------

/// Whether text is a PDDL name: a letter, then letters, digits, '-' and '_'.
bool is_pddl_name(std::string_view text) {
    if (text.empty() || !std::isalpha(static_cast<unsigned char>(text[0]))) {
        return false;
    }
    return std::all_of(text.begin(), text.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
    });
}

/// The source text from the start of e to `end` (an offset in e's file).
std::string_view text_to(const Expr& e, std::uint32_t end, const SourceManager& sources) {
    return sources.text(e.range.file).substr(e.range.begin, end - e.range.begin);
}

/// `courier-in` parses as a subtraction and `crate-at_1(c)` as one whose right side is a call:
/// written without spaces, they are the name (or the call of the name) where it is known.
void spell(Expr& e, const SourceManager& sources, const std::set<std::string>& known) {
    if (e.is_binary("-") && e.range.valid()) {
        const Expr* right = &e.args[1];
        if (right->kind == Expr::Kind::Call) {
            std::string name(text_to(e, right->name_range.end, sources));
            if (is_pddl_name(name) && known.count(name)) {
                Expr call = *right;
                call.text = name;
                call.name_range = SourceRange{e.range.file, e.range.begin, right->name_range.end};
                call.range = e.range;
                e = std::move(call);
                for (auto& a : e.args) {
                    spell(a, sources, known);
                }
                return;
            }
        } else {
            std::string name(text_to(e, e.range.end, sources));
            if (is_pddl_name(name) && known.count(name)) {
                e.kind = Expr::Kind::Name;
                e.text = name;
                e.args.clear();
                return;
            }
        }
    }
    for (auto& a : e.args) {
        spell(a, sources, known);
    }
    if (e.macro) {
        auto copy = std::make_shared<MacroCall>(*e.macro);
        for (auto& h : copy->header) {
            spell(h, sources, known);
        }
        for (auto& b : copy->body) {
            spell(b, sources, known);
        }
        e.macro = std::move(copy);
    }
}

// ---- entries PDDL implies ----------------------------------------------------------------------

/// A source is-a path from type object `from` up to `to` (empty when equal), or nullopt; along
/// the first parent that leads there (a type may have several: pddl.hpp).
std::optional<std::vector<HomId>> is_a_path(const pddl::Import& s, ObId from, ObId to) {
    if (from == to) {
        return std::vector<HomId>{};
    }
    const std::string* t = s.type_of(from);
    auto it = t == nullptr ? s.is_a.end() : s.is_a.find(*t);
    if (it == s.is_a.end()) {
        return std::nullopt;
    }
    for (HomId h : it->second) {
        if (auto rest = is_a_path(s, s.domain->schema->hom(h).codom, to)) {
            rest->insert(rest->begin(), h);
            return rest;
        }
    }
    return std::nullopt;
}

class Completion {
public:
    Completion(const pddl::Import& t, const pddl::Import& s, SchemaMap& f,
               const std::function<bool(Generator)>& has_entry, SourceRange at)
        : t_(t), s_(s), f_(f), has_(has_entry), at_(at) {}

    void run() {
        const Schema& ts = *t_.domain->schema;
        if (!has_({GeneratorKind::AttrType, t_.name_type.index()})) {
            f_.map_attr_type(t_.name_type, s_.name_type, at_);
        }
        for (const auto& [type, homs] : t_.is_a) {
            for (HomId h : homs) {
                if (!has_({GeneratorKind::Hom, h.index()})) {
                    to_type(h, ts.hom(h).dom, ts.hom(h).codom, std::nullopt);
                }
            }
        }
        for (const auto& [pred, homs] : t_.predicate_homs) {
            for (std::size_t i = 0; i < homs.size(); ++i) {
                if (!has_({GeneratorKind::Hom, homs[i].index()})) {
                    to_type(homs[i], ts.hom(homs[i]).dom, ts.hom(homs[i]).codom, i);
                }
            }
        }
        for (const auto& [type, a] : t_.name_attr) {
            if (!has_({GeneratorKind::Attr, a.index()})) {
                name(a, ts.attr(a).dom);
            }
        }
    }

private:
    /// The query of a target object, when it has an entry that is not @empty.
    const Query* query(ObId c) const {
        if (!has_({GeneratorKind::Ob, c.index()})) {
            return nullptr;
        }
        const Query& q = f_.query(c);
        return q.is_empty() ? nullptr : &q;
    }

    /// A hom into a type: from the variable of its domain's query that reaches the codomain's
    /// type, along the source's argument hom `leg` (for a predicate's argument) and is-a homs.
    void to_type(HomId h, ObId dom, ObId codom, std::optional<std::size_t> leg) {
        const Query* qd = query(dom);
        const Query* qc = query(codom);
        if (qd == nullptr || qc == nullptr || !qc->is_plain()) {
            return; // an @empty domain needs no image; other shapes are the map's to write
        }
        ObId to = qc->nodes()[0].ob;
        for (const auto& n : qd->nodes()) {
            if (n.is_value) {
                continue;
            }
            std::vector<HomId> path;
            ObId at = n.ob;
            if (leg) {
                const std::string* pred = s_.predicate_of(n.ob);
                if (pred == nullptr || s_.predicate_homs.at(*pred).size() <= *leg) {
                    continue;
                }
                path.push_back(s_.predicate_homs.at(*pred)[*leg]);
                at = s_.domain->schema->hom(path.back()).codom;
            }
            auto up = is_a_path(s_, at, to);
            if (!up) {
                continue;
            }
            path.insert(path.end(), up->begin(), up->end());
            if (qd->is_plain()) {
                f_.map_hom_path(h, path, at_);
            } else {
                f_.map_hom(h, {Term::path(n.name, path, std::nullopt, at_)}, at_);
            }
            return;
        }
    }

    /// A type's name: the name of the first variable of its query over a source type.
    void name(AttrId a, ObId c) {
        const Query* q = query(c);
        if (q == nullptr) {
            return;
        }
        for (const auto& n : q->nodes()) {
            const std::string* type = n.is_value ? nullptr : s_.type_of(n.ob);
            if (type != nullptr) {
                f_.map_attr(a, Term::path(n.name, {}, s_.name_attr.at(*type), at_), at_);
                return;
            }
        }
    }

    const pddl::Import& t_;
    const pddl::Import& s_;
    SchemaMap& f_;
    const std::function<bool(Generator)>& has_;
    SourceRange at_;
};

/// The PDDL import of a schema, or nullptr.
const pddl::Import* pddl_of(const Elaborator& ctx, const Schema& s) {
    for (const auto& [name, im] : ctx.pddl_domains) {
        if (im->domain->schema.get() == &s) {
            return im.get();
        }
    }
    return nullptr;
}

} // namespace

bool is_pddl_path(std::string_view path) {
    return path.size() > 5 && path.substr(path.size() - 5) == ".pddl";
}

void import_pddl_file(Elaborator& ctx, std::uint32_t file, SourceRange at, bool imported) {
    std::string_view text = ctx.sources.text(file);
    if (!at.valid()) {
        // A file read alone: its messages point at its first form.
        auto b = static_cast<std::uint32_t>(skip_blanks(text, 0));
        at = SourceRange{file, b, b + (b < text.size() ? 1U : 0U)};
    }
    std::string kind = pddl_kind(text);
    if (kind == "domain") {
        declare_domain(ctx, file, imported);
    } else if (kind == "problem") {
        declare_problem(ctx, file, at, imported);
    } else {
        ctx.sink.error(at, "expected a PDDL domain or problem: '(define (domain NAME) ...)' or "
                           "'(define (problem NAME) ...)'");
    }
}

void spell_pddl_names(const Elaborator& ctx, MacroCall& form) {
    if (ctx.pddl_domains.empty()) {
        return;
    }
    std::set<std::string> known;
    for (const auto& [name, im] : ctx.pddl_domains) {
        known.insert(name);
        const Schema& s = *im->domain->schema;
        for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
            known.insert(s.ob(ObId(i)).name);
        }
        for (std::uint32_t i = 0; i < s.num_homs(); ++i) {
            known.insert(s.hom(HomId(i)).name);
        }
        for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
            known.insert(s.attr(AttrId(i)).name);
        }
        for (const auto& a : im->pddl_domain.actions) {
            known.insert(a.name);
        }
        for (const auto& f : im->pddl_domain.functions) {
            known.insert(f.name);
        }
    }
    for (auto& h : form.header) {
        spell(h, ctx.sources, known);
    }
    for (auto& b : form.body) {
        spell(b, ctx.sources, known);
    }
}

namespace {

/// `source_action => target_action` of an actions section.
void read_action(const Expr& e, const pddl::Import* t, const pddl::Import* s, DiagnosticSink& sink,
                 MapSections& out) {
    const std::string &from = e.args[0].text, &to = e.args[1].text;
    if (s != nullptr && s->pddl_domain.find_action(from) == nullptr) {
        sink.error(e.args[0].range, fmt::format("'{}' is not an action of the source domain '{}'",
                                                from, s->pddl_domain.name));
    } else if (t != nullptr && t->pddl_domain.find_action(to) == nullptr) {
        sink.error(e.args[1].range, fmt::format("'{}' is not an action of the target domain '{}'",
                                                to, t->pddl_domain.name));
    } else {
        out.actions.push_back({from, to, e.range});
    }
}

/// The function `name` of the domain an action's cost may read, or nullptr with the error.
const pddl::Function* cost_function(const Expr& name, const pddl::Import& im, const char* side,
                                    DiagnosticSink& sink) {
    const pddl::Function* f = im.pddl_domain.find_function(name.text);
    if (f == nullptr || f->name == "total-cost") {
        sink.error(name.range, fmt::format("'{}' is not a function of the {} domain '{}'{}",
                                           name.text, side, im.pddl_domain.name,
                                           f != nullptr ? " whose values a problem gives" : ""));
        return nullptr;
    }
    return f;
}

/// `target_function => source_function` of a functions section.
void read_function(const Expr& e, const pddl::Import& t, const pddl::Import& s,
                   DiagnosticSink& sink, MapSections& out) {
    const auto* to = cost_function(e.args[0], t, "target", sink);
    const auto* from = cost_function(e.args[1], s, "source", sink);
    if (to == nullptr || from == nullptr) {
        return;
    }
    if (to->params.size() != from->params.size()) {
        sink.error(e.range,
                   fmt::format("'{}' takes {} argument(s) and '{}' {}: a function "
                               "takes the values of one with as many",
                               to->name, to->params.size(), from->name, from->params.size()));
        return;
    }
    for (const auto& c : out.functions) {
        if (c.target == to->name) {
            sink.error(e.args[0].range, fmt::format("'{}' is given twice in the functions "
                                                    "section",
                                                    to->name));
            return;
        }
    }
    out.functions.push_back({to->name, from->name, e.range});
}

} // namespace

void add_pddl_hooks(const Elaborator& ctx, MapForm& mf, MapSections& sections) {
    const pddl::Import* t = pddl_of(ctx, *mf.target);
    const pddl::Import* s = pddl_of(ctx, *mf.source);
    SourceRange at = mf.name_range;
    if (t != nullptr && s != nullptr) {
        mf.complete = [t, s, at](SchemaMap& f, const std::function<bool(Generator)>& has) {
            Completion(*t, *s, f, has, at).run();
        };
    }
    DiagnosticSink* sink = &ctx.sink;
    mf.other_statement = [t, s, sink, &sections](const Expr& st) {
        if (!st.is_binary("=>") || st.args[0].kind != Expr::Kind::Name ||
            st.args[1].kind != Expr::Kind::Block ||
            (st.args[0].text != "actions" && st.args[0].text != "functions")) {
            return false;
        }
        bool actions = st.args[0].text == "actions";
        if (!actions && (t == nullptr || s == nullptr)) {
            sink->error(st.range, "a functions section needs a map between two PDDL domains");
            return true;
        }
        for (const Expr& e : st.args[1].args) {
            if (!e.is_binary("=>") || e.args[0].kind != Expr::Kind::Name ||
                e.args[1].kind != Expr::Kind::Name) {
                sink->error(e.range, fmt::format("expected '{}' in the {} section, found '{}'",
                                                 actions ? "source_action => target_action"
                                                         : "target_function => source_function",
                                                 st.args[0].text, to_string(e)));
            } else if (actions) {
                read_action(e, t, s, *sink, sections);
            } else {
                read_function(e, *t, *s, *sink, sections);
            }
        }
        return true;
    };
}

} // namespace catplan::lang::detail
