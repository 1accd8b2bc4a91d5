// Ontology maps in the language: the entries of `@migration Name(Target, Source) begin ... end`
// (docs/language.md, "Ontology maps") elaborated into a migrate::SchemaMap, and a map printed back
// in brief.

#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/detail/map_elaboration.hpp"
#include "catplan/lang/module.hpp"

#include <fmt/format.h>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace catplan::lang {
namespace {

using acset::Value;
using migrate::Query;
using migrate::SchemaMap;
using migrate::Term;
using schema::Generator;
using schema::GeneratorKind;
using schema::Schema;
using schema::ValueKind;

// The literal as a value; an Int literal becomes a Float where a Float is wanted.
Value literal_value(const Expr& e, ValueKind want) {
    switch (e.kind) {
    case Expr::Kind::Int:
        return want == ValueKind::Float ? Value::real(static_cast<double>(e.int_value))
                                        : Value::integer(e.int_value);
    case Expr::Kind::Float:
        return Value::real(e.float_value);
    case Expr::Kind::String:
        return Value::string(e.text);
    default:
        return Value::boolean(e.bool_value);
    }
}

// `f ⋅ g ⋅ h` and `compose(f, g, h)` as their factors, in order.
void flatten_path(const Expr& e, std::vector<const Expr*>& out) {
    if (e.is_binary(".")) {
        flatten_path(e.args[0], out);
        flatten_path(e.args[1], out);
    } else if (e.kind == Expr::Kind::Call && e.text == "compose") {
        for (const auto& a : e.args) {
            flatten_path(a, out);
        }
    } else {
        out.push_back(&e);
    }
}

std::string node_names(const Query& q) {
    std::string out;
    for (const auto& n : q.nodes()) {
        out += (out.empty() ? "" : ", ") + n.name;
    }
    return out.empty() ? "none" : out;
}

/// `bus-at` read as the subtraction `bus - at`: the name it spells, or nullopt for another
/// expression.
std::optional<std::string> hyphenated(const Expr& e) {
    if (e.kind == Expr::Kind::Name) {
        return e.text;
    }
    if (!e.is_binary("-")) {
        return std::nullopt;
    }
    auto left = hyphenated(e.args[0]);
    auto right = hyphenated(e.args[1]);
    if (!left || !right) {
        return std::nullopt;
    }
    return *left + "-" + *right;
}

class MapElaborator {
public:
    MapElaborator(const detail::MapForm& form, DiagnosticSink& sink)
        : form_(form),
          sink_(sink),
          t_(*form.target),
          s_(*form.source),
          map_(std::make_shared<SchemaMap>(form.target, form.source)) {}

    std::shared_ptr<const SchemaMap> run() {
        std::size_t errors = sink_.num_errors();
        // Objects and attribute types first: an image of a hom or an attribute is read against
        // the queries of its ends, wherever their entries are written.
        std::vector<std::pair<Generator, const Expr*>> later;
        for (const Expr& st : *form_.body) {
            if (form_.other_statement && form_.other_statement(st)) {
                continue;
            }
            auto g = entry_generator(st);
            if (!g) {
                continue;
            }
            attempted_.insert(key(*g));
            entries_[key(*g)] = st.range;
            if (g->kind == GeneratorKind::Ob) {
                map_object(ObId(g->index), st);
            } else if (g->kind == GeneratorKind::AttrType) {
                map_attr_type(AttrTypeId(g->index), st);
            } else {
                later.emplace_back(*g, &st);
            }
        }
        for (const auto& [g, st] : later) {
            if (g.kind == GeneratorKind::Hom) {
                map_hom(HomId(g.index), *st);
            } else {
                map_attr(AttrId(g.index), *st);
            }
        }
        if (form_.complete) {
            form_.complete(*map_, [&](Generator g) { return attempted_.count(key(g)) != 0; });
        }
        report(map_->finish());
        check_declared_kinds();
        return sink_.num_errors() == errors ? map_ : nullptr;
    }

private:
    using Key = std::pair<int, std::uint32_t>;

    static Key key(Generator g) { return {static_cast<int>(g.kind), g.index}; }

    void error(SourceRange at, std::string message) { sink_.error(at, std::move(message)); }

    // The target generator an entry `X => image` maps; reports a malformed or unknown one.
    std::optional<Generator> entry_generator(const Expr& st) {
        if (!st.is_binary("=>")) {
            error(st.range, fmt::format("expected an entry 'Generator => image' of map '{}', "
                                        "found '{}'",
                                        form_.name, to_string(st)));
            return std::nullopt;
        }
        const Expr& lhs = st.args[0];
        if (lhs.kind != Expr::Kind::Name) {
            auto joined = hyphenated(lhs);
            auto meant = joined ? t_.find(*joined) : std::nullopt;
            std::string hint;
            if (meant) {
                attempted_.insert(key(*meant)); // not reported again as unmapped
                hint = fmt::format(" (the name '{}' is written var\"{}\" in a map whose schemas "
                                   "are not PDDL imports)",
                                   *joined, *joined);
            }
            error(lhs.range, fmt::format("expected a generator of '{}' before '=>', found '{}'{}",
                                         t_.name(), to_string(lhs), hint));
            return std::nullopt;
        }
        auto g = t_.find(lhs.text);
        if (!g) {
            error(lhs.range, fmt::format("'{}' is not a generator of the target schema '{}'",
                                         lhs.text, t_.name()));
        }
        return g;
    }

    // Every problem of the finished map, located at its entry; an unmapped generator at the
    // map's name. A generator whose entry already failed is not reported again as unmapped.
    void report(const std::vector<migrate::MapProblem>& problems) {
        for (const auto& p : problems) {
            if (p.kind == migrate::MapProblemKind::Unmapped && attempted_.count(key(p.target))) {
                continue;
            }
            SourceRange at = p.range.valid() ? p.range : form_.name_range;
            std::string message = p.kind == migrate::MapProblemKind::Unmapped
                                      ? fmt::format("map '{}': {}", form_.name, p.message)
                                      : p.message;
            // An equation is located in the schema; the error belongs to the map's entry.
            auto entry = entries_.find(key(p.target));
            bool relocate =
                p.kind == migrate::MapProblemKind::EquationNotPreserved && entry != entries_.end();
            if (relocate) {
                at = entry->second;
            }
            auto& d = p.severity == Severity::Error ? sink_.error(at, std::move(message))
                                                    : sink_.warning(at, std::move(message));
            if (relocate && p.range.valid()) {
                d.notes.emplace_back(p.range, "the equation is declared here");
            }
        }
    }

    // A target attribute type with a declared kind must be sent to values of that kind.
    void check_declared_kinds() {
        for (std::uint32_t i = 0; i < t_.num_attr_types(); ++i) {
            AttrTypeId tt(i);
            auto it = entries_.find(key({GeneratorKind::AttrType, i}));
            ValueKind want = t_.attr_type(tt).kind;
            ValueKind got = map_->attr_type_kind(tt);
            if (it == entries_.end() || want == ValueKind::Unknown || got == ValueKind::Unknown ||
                want == got) {
                continue;
            }
            error(it->second, fmt::format("'{}' holds {} values in '{}' but is sent to {}",
                                          t_.attr_type(tt).name, schema::to_string(want), t_.name(),
                                          schema::to_string(got)));
        }
    }

    // ---- objects: plain entries and queries ----------------------------------------------------

    void map_object(ObId c, const Expr& st) {
        const Expr& rhs = st.args[1];
        if (rhs.kind == Expr::Kind::Name) {
            if (auto ob = source_ob(rhs)) {
                map_->map_ob(c, *ob, st.range);
                mapped_.insert(c.index());
            }
            return;
        }
        if (rhs.kind != Expr::Kind::Macro) {
            error(rhs.range, fmt::format("expected an object of '{}' or a query (@join, "
                                         "@product, @unit, @empty) for '{}', found '{}'",
                                         s_.name(), t_.ob(c).name, to_string(rhs)));
            return;
        }
        const MacroCall& m = *rhs.macro;
        Query q(form_.source);
        if (m.name == "join" || m.name == "limit" || m.name == "product") {
            for (const Expr* q_st : query_statements(m)) {
                query_statement(q, *q_st, m.name == "product");
            }
        } else if (m.name == "empty" || m.name == "initial") {
            q.set_empty();
        } else if (m.name == "unit" || m.name == "terminal") {
            // The query with no variables: one tuple in every state.
        } else if (m.name == "cases" || m.name == "coproduct" || m.name == "glue" ||
                   m.name == "colimit") {
            error(m.name_range, gluing_query_message(m.name, t_.ob(c).name));
            return;
        } else {
            error(m.name_range, fmt::format("unknown query '@{}' (expected @join, @product, "
                                            "@unit or @empty)",
                                            m.name));
            return;
        }
        map_->map_ob(c, std::move(q), st.range);
        mapped_.insert(c.index());
    }

    // A plan transfers along conjunctive maps only (Δ of a query is where the paper's guarantees
    // hold), so a gluing query gets the ways to say it conjunctively.
    static std::string gluing_query_message(const std::string& macro, const std::string& ob) {
        bool cases = macro == "cases" || macro == "coproduct";
        return fmt::format(
            "'@{}' is a gluing query, which maps do not support (only conjunctive ones: @join, "
            "@product, @unit, @empty); {}",
            macro,
            cases ? fmt::format("give each case an object of its own in the target schema (one "
                                "entry per case, each an object or a @join) instead of one '{}'",
                                ob)
                  : fmt::format("map '{}' to the @join of the parts to be glued and identify "
                                "them in the states, or keep the quotient out of the map",
                                ob));
    }

    std::optional<ObId> source_ob(const Expr& e) {
        if (e.kind == Expr::Kind::Name) {
            if (auto ob = s_.find_ob(e.text)) {
                return ob;
            }
        }
        unknown_in_source(e, "an object");
        return std::nullopt;
    }

    void unknown_in_source(const Expr& e, std::string_view wanted) {
        if (e.kind == Expr::Kind::Name && s_.find(e.text)) {
            error(e.range, fmt::format("'{}' is not {} of the source schema '{}'", e.text, wanted,
                                       s_.name()));
        } else {
            error(e.range,
                  fmt::format("unknown {} '{}' in the source schema '{}'",
                              wanted.substr(wanted.find(' ') + 1), to_string(e), s_.name()));
        }
    }

    // The statements of `@join begin ... end`, `@join (a; b)` or `@join a`.
    static std::vector<const Expr*> query_statements(const MacroCall& m) {
        std::vector<const Expr*> out;
        if (m.has_body) {
            for (const auto& st : m.body) {
                out.push_back(&st);
            }
            return out;
        }
        for (const auto& h : m.header) {
            if (h.kind == Expr::Kind::Tuple || h.kind == Expr::Kind::Block) {
                for (const auto& st : h.args) {
                    out.push_back(&st);
                }
            } else {
                out.push_back(&h);
            }
        }
        return out;
    }

    void query_statement(Query& q, const Expr& st, bool product) {
        if (st.is_binary("::") &&
            (st.args[0].kind == Expr::Kind::Name || st.args[0].kind == Expr::Kind::Tuple)) {
            declare_nodes(q, st);
        } else if (!product && st.is_binary("::") &&
                   (st.args[0].is_binary(":") || st.args[0].is_binary("->"))) {
            edge(q, st);
        } else if (!product && st.is_binary("==")) {
            equation(q, st.args[0], st.args[1], st.range);
        } else {
            error(st.range, fmt::format("expected {}, found '{}'",
                                        product ? "a variable 'x::Ob' (a @product has no edges)"
                                                : "a variable 'x::Ob', an edge '(f: x → y)::h' "
                                                  "or an equation 'h(x) == y'",
                                        to_string(st)));
        }
    }

    void declare_nodes(Query& q, const Expr& st) {
        std::vector<const Expr*> names;
        if (st.args[0].kind == Expr::Kind::Name) {
            names.push_back(&st.args[0]);
        } else {
            for (const auto& a : st.args[0].args) {
                if (a.kind != Expr::Kind::Name) {
                    error(a.range,
                          fmt::format("expected a variable name, found '{}'", to_string(a)));
                    return;
                }
                names.push_back(&a);
            }
        }
        const Expr& type = st.args[1];
        std::optional<ObId> ob =
            type.kind == Expr::Kind::Name ? s_.find_ob(type.text) : std::nullopt;
        std::optional<AttrTypeId> t =
            type.kind == Expr::Kind::Name ? s_.find_attr_type(type.text) : std::nullopt;
        if (!ob && !t) {
            unknown_in_source(type, "an object or attribute type");
            return;
        }
        for (const Expr* n : names) {
            if (ob) {
                q.add_variable(n->text, *ob, n->range);
            } else {
                q.add_value_variable(n->text, *t, n->range);
            }
        }
    }

    // `(f: x → y)::h` or `(x → y)::h`: x ⋅ h == y; `::(x -> "purple")` fixes y to the constant.
    void edge(Query& q, const Expr& st) {
        const Expr& arrow = st.args[0].is_binary(":") ? st.args[0].args[1] : st.args[0];
        if (!arrow.is_binary("->") || arrow.args[0].kind != Expr::Kind::Name ||
            arrow.args[1].kind != Expr::Kind::Name) {
            error(arrow.range, fmt::format("expected an edge 'x → y' between variables, found '{}'",
                                           to_string(arrow)));
            return;
        }
        auto y = node_term(q, arrow.args[1]);
        const Expr& label = st.args[1];
        if (label.is_binary("->")) {
            const Expr& body = label.args[1];
            if (!detail::is_literal(body)) {
                error(body.range, fmt::format("only a constant function such as (x -> \"red\") "
                                              "can label an edge, found '{}'",
                                              to_string(label)));
                return;
            }
            if (y) {
                equation(q, arrow.args[1], body, st.range);
            }
            return;
        }
        auto x = node_term(q, arrow.args[0]);
        if (!x || !y || !extend(*x, label)) {
            return;
        }
        x->range = st.range;
        q.add_equation(*x, *y, st.range);
    }

    void equation(Query& q, const Expr& lhs, const Expr& rhs, SourceRange at) {
        auto l = term(q, lhs);
        auto r = term(q, rhs);
        if (!l || !r) {
            return;
        }
        // An Int literal against a Float attribute is the Float.
        fix_literal(q, *l, *r, rhs);
        fix_literal(q, *r, *l, lhs);
        q.add_equation(*l, *r, at);
    }

    void fix_literal(const Query& q, const Term& other, Term& lit, const Expr& lit_expr) {
        if (!lit.is_literal() || lit_expr.kind != Expr::Kind::Int) {
            return;
        }
        if (term_kind(q, other) == ValueKind::Float) {
            lit.literal = Value::real(static_cast<double>(lit_expr.int_value));
        }
    }

    ValueKind term_kind(const Query& q, const Term& t) const {
        if (t.attr) {
            return s_.attr_type(s_.attr(*t.attr).codom).kind;
        }
        if (auto n = q.find_node(t.var); n && q.nodes()[*n].is_value) {
            return s_.attr_type(q.nodes()[*n].type).kind;
        }
        return ValueKind::Unknown;
    }

    // ---- terms ---------------------------------------------------------------------------------

    std::optional<Term> node_term(const Query& q, const Expr& e) {
        if (e.kind == Expr::Kind::Name && q.find_node(e.text)) {
            return Term::path(e.text, {}, std::nullopt, e.range);
        }
        error(e.range, fmt::format("unknown variable '{}' (the query's variables: {})",
                                   to_string(e), node_names(q)));
        return std::nullopt;
    }

    // A term of query q: a literal, `x`, `f(x)`, `x ⋅ f ⋅ attr` or `attr(f(x))`.
    std::optional<Term> term(const Query& q, const Expr& e) {
        if (detail::is_literal(e)) {
            return Term::constant(literal_value(e, ValueKind::Unknown), e.range);
        }
        std::optional<Term> t;
        if (e.kind == Expr::Kind::Call && e.args.size() == 1 && e.text != "compose") {
            t = term(q, e.args[0]);
            Expr callee;
            callee.kind = Expr::Kind::Name;
            callee.text = e.text;
            callee.range = e.name_range;
            if (!t || !extend(*t, callee)) {
                return std::nullopt;
            }
        } else if (e.is_binary(".")) {
            std::vector<const Expr*> parts;
            flatten_path(e, parts);
            t = term(q, *parts[0]);
            for (std::size_t i = 1; t && i < parts.size(); ++i) {
                if (!extend(*t, *parts[i])) {
                    return std::nullopt;
                }
            }
        } else {
            t = node_term(q, e);
        }
        if (t) {
            t->range = e.range;
        }
        return t;
    }

    // Appends a hom, an attribute or a path to a term; reports names that are neither.
    bool extend(Term& t, const Expr& e) {
        std::vector<const Expr*> parts;
        flatten_path(e, parts);
        for (const Expr* p : parts) {
            if (t.is_literal() || t.attr) {
                error(p->range, fmt::format("cannot follow '{}' after {}", to_string(*p),
                                            t.is_literal() ? "a literal" : "an attribute"));
                return false;
            }
            if (p->kind == Expr::Kind::Name) {
                if (auto h = s_.find_hom(p->text)) {
                    t.homs.push_back(*h);
                    continue;
                }
                if (auto a = s_.find_attr(p->text)) {
                    t.attr = *a;
                    continue;
                }
            }
            unknown_in_source(*p, "a hom or attribute");
            return false;
        }
        return true;
    }

    // ---- homs ----------------------------------------------------------------------------------

    void map_hom(HomId f, const Expr& st) {
        ObId c = t_.hom(f).dom, d = t_.hom(f).codom;
        if (!mapped_.count(c.index()) || !mapped_.count(d.index())) {
            return; // the end's own entry is missing or reported
        }
        const Query& qc = map_->query(c);
        const Query& qd = map_->query(d);
        const Expr& rhs = st.args[1];
        if (rhs.kind == Expr::Kind::Block || rhs.kind == Expr::Kind::Tuple || rhs.is_binary("=>")) {
            node_map(f, qc, qd, rhs, st.range);
            return;
        }
        std::vector<const Expr*> parts;
        flatten_path(rhs, parts);
        const Expr& first = *parts[0];
        bool from_node = (first.kind == Expr::Kind::Name && qc.find_node(first.text) &&
                          !(qc.is_plain() && s_.find_hom(first.text))) ||
                         (first.kind == Expr::Kind::Call && first.text != "id");
        if (from_node) {
            auto t = term(qc, rhs);
            if (t) {
                map_->map_hom(f, {*t}, st.range);
            }
            return;
        }
        std::vector<HomId> path;
        for (const Expr* p : parts) {
            if (p->kind == Expr::Kind::Call && p->text == "id" && p->args.size() == 1) {
                (void)source_ob(p->args[0]);
                continue;
            }
            auto h = p->kind == Expr::Kind::Name ? s_.find_hom(p->text) : std::nullopt;
            if (!h) {
                if (p->kind == Expr::Kind::Name && !s_.find(p->text)) {
                    error(p->range,
                          fmt::format("'{}' is neither a hom of '{}' nor a variable of "
                                      "the query of '{}' (variables: {})",
                                      to_string(*p), s_.name(), t_.ob(c).name, node_names(qc)));
                } else {
                    unknown_in_source(*p, "a hom");
                }
                return;
            }
            path.push_back(*h);
        }
        map_->map_hom_path(f, std::move(path), st.range);
    }

    // `(y => x; z => w ⋅ h)` / `begin y => x end`: each variable of the codomain's query sent to
    // a term of the domain's query.
    void node_map(HomId f, const Query& qc, const Query& qd, const Expr& rhs, SourceRange at) {
        std::vector<const Expr*> items;
        if (rhs.is_binary("=>")) {
            items.push_back(&rhs);
        } else {
            for (const auto& a : rhs.args) {
                items.push_back(&a);
            }
        }
        std::vector<std::optional<Term>> images(qd.nodes().size());
        bool ok = true;
        for (const Expr* item : items) {
            if (!item->is_binary("=>") || item->args[0].kind != Expr::Kind::Name) {
                error(item->range,
                      fmt::format("expected 'variable => term', found '{}'", to_string(*item)));
                ok = false;
                continue;
            }
            const Expr& y = item->args[0];
            auto i = qd.find_node(y.text);
            if (!i) {
                error(y.range, fmt::format("'{}' is not a variable of the query of '{}' "
                                           "(variables: {})",
                                           y.text, t_.ob(t_.hom(f).codom).name, node_names(qd)));
                ok = false;
                continue;
            }
            if (images[*i]) {
                error(y.range, fmt::format("variable '{}' is given two images", y.text));
                ok = false;
                continue;
            }
            images[*i] = term(qc, item->args[1]);
            ok = ok && images[*i].has_value();
        }
        std::vector<Term> terms;
        for (std::size_t i = 0; ok && i < images.size(); ++i) {
            if (!images[i]) {
                error(at,
                      fmt::format("'{}': variable '{}' of the query of '{}' has no image",
                                  t_.hom(f).name, qd.nodes()[i].name, t_.ob(t_.hom(f).codom).name));
                ok = false;
            } else {
                terms.push_back(*images[i]);
            }
        }
        if (ok) {
            map_->map_hom(f, std::move(terms), at);
        }
    }

    // ---- attribute types and attributes --------------------------------------------------------

    void map_attr_type(AttrTypeId tt, const Expr& st) {
        const Expr& rhs = st.args[1];
        if (rhs.kind == Expr::Kind::Name) {
            if (auto t = s_.find_attr_type(rhs.text)) {
                map_->map_attr_type(tt, *t, st.range);
                return;
            }
            if (auto k = schema::parse_value_kind(rhs.text)) {
                map_->map_attr_type(tt, *k, st.range);
                return;
            }
        }
        error(rhs.range, fmt::format("expected an attribute type of '{}' or a value kind (Bool, "
                                     "Int, Float64, String) for '{}', found '{}'",
                                     s_.name(), t_.attr_type(tt).name, to_string(rhs)));
    }

    void map_attr(AttrId a, const Expr& st) { map_attr_image(a, st.args[1], st.range); }

    void map_attr_image(AttrId a, const Expr& rhs, SourceRange at) {
        ValueKind want = map_->attr_type_kind(t_.attr(a).codom);
        if (detail::is_literal(rhs)) {
            map_->map_attr_constant(a, literal_value(rhs, want), at);
            return;
        }
        if (rhs.is_binary("|>")) {
            map_attr_pipe(a, rhs, at);
            return;
        }
        if (rhs.is_binary("->")) {
            const Expr& body = rhs.args[1];
            if (!detail::is_literal(body)) {
                error(body.range, fmt::format("only a constant function such as (x -> 0.0) can "
                                              "be written for '{}'; send it to a term such as "
                                              "label(x) instead",
                                              t_.attr(a).name));
                return;
            }
            map_->map_attr_constant(a, literal_value(body, want), at);
            return;
        }
        ObId c = t_.attr(a).dom;
        if (!mapped_.count(c.index())) {
            return;
        }
        const Query& qc = map_->query(c);
        std::vector<const Expr*> parts;
        flatten_path(rhs, parts);
        const Expr& first = *parts[0];
        bool from_node = (first.kind == Expr::Kind::Name && qc.find_node(first.text)) ||
                         first.kind == Expr::Kind::Call;
        std::optional<Term> t;
        if (from_node) {
            t = term(qc, rhs);
        } else if (qc.nodes().empty() || qc.nodes()[0].is_value) {
            error(rhs.range, fmt::format("the query of '{}' has no object variable for '{}' to "
                                         "start from",
                                         t_.ob(c).name, to_string(rhs)));
            return;
        } else {
            // A bare path `f ⋅ label` starts at the query's first variable.
            t = Term::path(qc.nodes()[0].name, {}, std::nullopt, rhs.range);
            if (!extend(*t, rhs)) {
                return;
            }
        }
        if (t) {
            map_->map_attr(a, *t, at);
        }
    }

    // Julia's pipe form, reference §5.3: `(x |> (v -> false))` is the constant false (x is read,
    // its value unused), `(label(x) |> (v -> v))` is label(x).
    void map_attr_pipe(AttrId a, const Expr& rhs, SourceRange at) {
        const Expr& fn = rhs.args[1];
        if (!fn.is_binary("->") || fn.args[0].kind != Expr::Kind::Name) {
            error(fn.range, fmt::format("expected a function such as (v -> false) after '|>' "
                                        "for '{}'",
                                        t_.attr(a).name));
            return;
        }
        const Expr& body = fn.args[1];
        if (body.kind == Expr::Kind::Name && body.text == fn.args[0].text) {
            map_attr_image(a, rhs.args[0], at); // the identity: the input itself
            return;
        }
        if (!detail::is_literal(body)) {
            error(body.range, fmt::format("only a constant function such as (v -> false) or the "
                                          "identity (v -> v) can follow '|>' for '{}'",
                                          t_.attr(a).name));
            return;
        }
        const Expr& input = rhs.args[0];
        ObId c = t_.attr(a).dom;
        if (input.kind == Expr::Kind::Name && mapped_.count(c.index()) &&
            !map_->query(c).find_node(input.text) && !s_.find(input.text)) {
            error(input.range, fmt::format("'{}' is neither a variable of the query of '{}' nor "
                                           "a generator of '{}'",
                                           input.text, t_.ob(c).name, s_.name()));
            return;
        }
        map_->map_attr_constant(a, literal_value(body, map_->attr_type_kind(t_.attr(a).codom)), at);
    }

    const detail::MapForm& form_;
    DiagnosticSink& sink_;
    const Schema& t_;
    const Schema& s_;
    std::shared_ptr<SchemaMap> map_;
    std::set<std::uint32_t> mapped_; // target objects with a query
    std::set<Key> attempted_;
    std::map<Key, SourceRange> entries_;
};

} // namespace

namespace detail {

std::shared_ptr<const migrate::SchemaMap> elaborate_map(const MapForm& form, DiagnosticSink& sink) {
    return MapElaborator(form, sink).run();
}

} // namespace detail

} // namespace catplan::lang
