#include "catplan/migrate/migration.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/hom/hom_search.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace catplan::migrate {

namespace {

// The images of a query's variables: a part (as an Int) or a value per variable.
using Key = std::vector<Value>;

struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
        std::uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (const Value& v : k) {
            h ^= v.hash() + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        }
        return static_cast<std::size_t>(h);
    }
};

// A total order on values: by kind (tag), then by value; strings by text.
bool value_less(const Value& a, const Value& b) {
    if (a.tag() != b.tag()) {
        return a.tag() < b.tag();
    }
    switch (a.tag()) {
    case Value::Tag::Unset:
        return false;
    case Value::Tag::Var:
        return a.var_index() < b.var_index();
    case Value::Tag::Bool:
        return a.as_bool() < b.as_bool();
    case Value::Tag::Int:
        return a.as_int() < b.as_int();
    case Value::Tag::Float:
        return a.as_float() < b.as_float();
    case Value::Tag::String:
        return a.as_string() < b.as_string();
    }
    return false;
}

} // namespace

namespace detail {

struct Tuples {
    enum class Mode : std::uint8_t { Empty, Plain, Scan, General };
    Mode mode = Mode::Empty;
    ObId ob; // Plain, Scan: the source object of the single part
    std::size_t count = 0;
    // Scan: the source part of each tuple, and the tuple of each source part (or kNoPart).
    std::vector<Part> scan_parts;
    std::vector<Part> scan_index;
    // General (and Scan for vars): rows of the assignment, object by object, type by type.
    std::vector<std::size_t> ob_offset, type_offset;
    std::size_t width = 0, var_width = 0;
    std::vector<Part> parts;
    std::vector<Value> vars;
    std::unordered_map<Key, std::uint32_t, KeyHash> index;

    Part part(std::size_t t, ObId x, Part q) const {
        switch (mode) {
        case Mode::Plain:
            return static_cast<Part>(t);
        case Mode::Scan:
            return scan_parts[t];
        default:
            return parts[t * width + ob_offset[x.index()] + q];
        }
    }

    Value var(std::size_t t, AttrTypeId type, std::uint32_t j) const {
        return vars[t * var_width + type_offset[type.index()] + j];
    }
};

} // namespace detail

MigratedState::MigratedState() : state(std::make_shared<schema::Schema>("")) {}

MigratedState::MigratedState(MigratedState&&) noexcept = default;
MigratedState& MigratedState::operator=(MigratedState&&) noexcept = default;
MigratedState::~MigratedState() = default;

namespace {

using detail::Tuples;

// The key of tuple t: the image of each variable of q.
Key tuple_key(const Query& q, const Tuples& tu, std::size_t t) {
    Key k;
    k.reserve(q.nodes().size());
    for (std::size_t i = 0; i < q.nodes().size(); ++i) {
        QueryElement el = q.locate_node(i);
        if (!el.is_value) {
            k.push_back(Value::integer(tu.part(t, el.ob, el.part)));
        } else if (el.value.is_var()) {
            k.push_back(tu.var(t, el.type, el.value.var_index()));
        } else {
            k.push_back(el.value);
        }
    }
    return k;
}

// The tuple of q whose variables have these images, if any.
std::optional<std::uint32_t> find_tuple(const Query& q, const Tuples& tu, const Key& k) {
    switch (tu.mode) {
    case Tuples::Mode::Empty:
        return std::nullopt;
    case Tuples::Mode::Plain:
    case Tuples::Mode::Scan: {
        // The single part is the first object variable's.
        for (std::size_t i = 0; i < q.nodes().size(); ++i) {
            if (!q.nodes()[i].is_value) {
                auto p = static_cast<Part>(k[i].as_int());
                if (tu.mode == Tuples::Mode::Plain) {
                    return p;
                }
                Part t = p < tu.scan_index.size() ? tu.scan_index[p] : kNoPart;
                if (t == kNoPart) {
                    return std::nullopt;
                }
                return t;
            }
        }
        return std::nullopt;
    }
    case Tuples::Mode::General: {
        auto it = tu.index.find(k);
        if (it == tu.index.end()) {
            return std::nullopt;
        }
        return it->second;
    }
    }
    return std::nullopt;
}

void set_offsets(Tuples& tu, const ACSet& shape) {
    const schema::Schema& s = shape.schema();
    tu.ob_offset.assign(s.num_obs(), 0);
    tu.type_offset.assign(s.num_attr_types(), 0);
    tu.width = 0;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        tu.ob_offset[o] = tu.width;
        tu.width += shape.num_parts(ObId(o));
    }
    tu.var_width = 0;
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        tu.type_offset[t] = tu.var_width;
        tu.var_width += shape.num_vars(AttrTypeId(t));
    }
}

// A single-part shape with only attribute filters: evaluated by scanning columns.
bool scan(const Query& q, const ACSet& x, Tuples& tu) {
    const ACSet& shape = q.state();
    if (shape.total_parts() != 1) {
        return false;
    }
    const schema::Schema& s = shape.schema();
    ObId ob;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (shape.num_parts(ObId(o)) == 1) {
            ob = ObId(o);
        }
    }
    for (HomId h : s.homs_from(ob)) {
        if (shape.subpart(h, 0) != kNoPart) {
            return false;
        }
    }

    struct Filter {
        std::span<const Value> column;
        Value literal;            // equal to this constant, or
        std::ptrdiff_t same = -1; // equal to the cell of this earlier filter, or
        bool set = false;         // merely set
    };

    std::vector<Filter> filters;
    // Where each variable of the shape is read from (its first cell).
    std::vector<std::vector<std::ptrdiff_t>> var_cell(s.num_attr_types());
    std::vector<std::pair<AttrTypeId, std::size_t>> var_filters; // type, filter index
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        var_cell[t].assign(shape.num_vars(AttrTypeId(t)), -1);
    }
    for (AttrId a : s.attrs_from(ob)) {
        const Value& v = shape.subpart(a, 0);
        if (v.is_unset()) {
            continue;
        }
        Filter f{x.column(a), Value(), -1, false};
        if (v.is_concrete()) {
            f.literal = v;
        } else {
            auto& cell = var_cell[s.attr(a).codom.index()][v.var_index()];
            if (cell < 0) {
                cell = static_cast<std::ptrdiff_t>(filters.size());
                f.set = true;
            } else {
                f.same = cell;
            }
        }
        filters.push_back(f);
    }
    tu.mode = Tuples::Mode::Scan;
    tu.ob = ob;
    set_offsets(tu, shape);
    std::size_t n = x.num_parts(ob);
    tu.scan_index.assign(n, kNoPart);
    // Filter by filter over the columns: the first literal filter picks candidates.
    std::vector<Part> cand;
    std::size_t first = filters.size();
    for (std::size_t i = 0; i < filters.size(); ++i) {
        if (filters[i].literal.is_concrete()) {
            first = i;
            break;
        }
    }
    if (first < filters.size()) {
        const Value lit = filters[first].literal;
        std::span<const Value> col = filters[first].column;
        for (Part p = 0; p < n; ++p) {
            if (col[p] == lit) {
                cand.push_back(p);
            }
        }
    } else {
        cand.resize(n);
        std::iota(cand.begin(), cand.end(), Part{0});
    }
    for (Part p : cand) {
        bool ok = true;
        for (std::size_t i = 0; ok && i < filters.size(); ++i) {
            if (i == first) {
                continue;
            }
            const Filter& f = filters[i];
            const Value& cell = f.column[p];
            if (f.literal.is_concrete()) {
                ok = cell == f.literal;
            } else if (f.set) {
                ok = !cell.is_unset();
            } else {
                ok = cell == filters[static_cast<std::size_t>(f.same)].column[p];
            }
        }
        if (ok) {
            tu.scan_index[p] = static_cast<Part>(tu.scan_parts.size());
            tu.scan_parts.push_back(p);
        }
    }
    tu.count = tu.scan_parts.size();
    if (tu.var_width > 0) {
        tu.vars.resize(tu.count * tu.var_width);
        for (std::size_t t = 0; t < tu.count; ++t) {
            for (std::uint32_t ty = 0; ty < s.num_attr_types(); ++ty) {
                for (std::size_t j = 0; j < var_cell[ty].size(); ++j) {
                    auto fi = static_cast<std::size_t>(var_cell[ty][j]);
                    tu.vars[t * tu.var_width + tu.type_offset[ty] + j] =
                        filters[fi].column[tu.scan_parts[t]];
                }
            }
        }
    }
    return true;
}

void general(const Query& q, const ACSet& x, Tuples& tu) {
    const ACSet& shape = q.state();
    tu.mode = Tuples::Mode::General;
    set_offsets(tu, shape);
    const schema::Schema& s = shape.schema();
    std::vector<Part> parts;
    std::vector<Value> vars;
    std::size_t count = 0;
    auto add = [&](const hom::ACSetMorphism& m) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            parts.insert(parts.end(), m.components[o].begin(), m.components[o].end());
        }
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            vars.insert(vars.end(), m.var_components[t].begin(), m.var_components[t].end());
        }
        ++count;
        return true;
    };
    bool no_vars = true;
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        no_vars = no_vars && shape.num_vars(AttrTypeId(t)) == 0;
    }
    if (shape.total_parts() == 0 && no_vars) {
        add(hom::identity(shape)); // `@unit`: one assignment, of nothing (no search to set up)
    } else {
        auto r = hom::for_each_homomorphism(shape, x, {}, add);
        CATPLAN_ASSERT(r.error.empty(), "a validated query has finitely many assignments");
    }
    // Lexicographic order of the variables' images.
    tu.count = count;
    tu.parts = std::move(parts);
    tu.vars = std::move(vars);
    std::vector<Key> keys(count);
    for (std::size_t t = 0; t < count; ++t) {
        keys[t] = tuple_key(q, tu, t);
    }
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0U);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return std::lexicographical_compare(keys[a].begin(), keys[a].end(), keys[b].begin(),
                                            keys[b].end(), value_less);
    });
    std::vector<Part> sorted_parts(tu.parts.size());
    std::vector<Value> sorted_vars(tu.vars.size());
    for (std::size_t i = 0; i < count; ++i) {
        std::copy_n(tu.parts.begin() + static_cast<std::ptrdiff_t>(order[i] * tu.width), tu.width,
                    sorted_parts.begin() + static_cast<std::ptrdiff_t>(i * tu.width));
        std::copy_n(tu.vars.begin() + static_cast<std::ptrdiff_t>(order[i] * tu.var_width),
                    tu.var_width,
                    sorted_vars.begin() + static_cast<std::ptrdiff_t>(i * tu.var_width));
        tu.index.emplace(std::move(keys[order[i]]), static_cast<std::uint32_t>(i));
    }
    tu.parts = std::move(sorted_parts);
    tu.vars = std::move(sorted_vars);
}

// The column of a path of X's homs out of an object with n parts: p goes to follow(x, p, path).
// Composed a column at a time: a copy of the first hom's column, then one gather per further hom.
std::vector<Part> path_column(const ACSet& x, std::size_t n, const std::vector<HomId>& path) {
    std::vector<Part> col;
    if (path.empty()) {
        col.resize(n);
        std::iota(col.begin(), col.end(), Part{0});
        return col;
    }
    std::span<const Part> first = x.column(path[0]);
    CATPLAN_ASSERT(first.size() == n, "a delta hom starts at the tuples' object");
    col.assign(first.begin(), first.end());
    for (std::size_t k = 1; k < path.size(); ++k) {
        std::span<const Part> next = x.column(path[k]);
        for (Part& p : col) {
            p = p == kNoPart ? kNoPart : next[p];
        }
    }
    return col;
}

// The names of the tuples at c: tuple i is named after the part of X assigned to the query's
// first object variable. Empty (no names) when X names no part of that variable's object.
std::vector<Symbol> tuple_names(const Query& q, const Tuples& tu, const ACSet& x) {
    std::vector<Symbol> names;
    auto n = q.first_object_node();
    if (!n || tu.count == 0) {
        return names;
    }
    QueryElement el = q.locate_node(*n);
    std::span<const Symbol> from = x.part_names(el.ob);
    if (from.empty()) {
        return names;
    }
    if (tu.mode == Tuples::Mode::Plain) {
        names.assign(from.begin(), from.end());
        return names;
    }
    names.resize(tu.count);
    for (std::size_t i = 0; i < tu.count; ++i) {
        names[i] = from[tu.part(i, el.ob, el.part)];
    }
    return names;
}

// The hom columns of Δ_F(X): a path's column between plain queries, else each tuple's image
// looked up among the codomain's tuples.
void migrate_homs(const SchemaMap& f, const ACSet& x, MigratedState& out) {
    const schema::Schema& t = *f.target();
    ACSet& y = out.state;
    for (std::uint32_t h = 0; h < t.num_homs(); ++h) {
        HomId fh(h);
        ObId c = t.hom(fh).dom, d = t.hom(fh).codom;
        const Tuples& tc = *out.tuples[c.index()];
        const Tuples& td = *out.tuples[d.index()];
        if (tc.count == 0) {
            continue;
        }
        const HomImage& im = f.hom_image(fh);
        if (im.path) {
            // Between plain queries: tuples are X's parts, so the column is the path's (for a
            // single hom, its column in X, copied straight across).
            if (im.path->size() == 1) {
                y.set_column(fh, x.column(im.path->front()));
            } else {
                y.set_column(fh, path_column(x, tc.count, *im.path));
            }
            continue;
        }
        const ACSetMorphism& qf = *im.morphism;
        const Query& qd = f.query(d);
        bool single = td.mode == Tuples::Mode::Plain || td.mode == Tuples::Mode::Scan;
        std::optional<std::size_t> dn = qd.first_object_node();
        std::vector<Part> col(tc.count, kNoPart);
        for (std::size_t i = 0; i < tc.count; ++i) {
            if (single && dn) {
                QueryElement el = qd.locate_node(*dn);
                Part p = tc.part(i, el.ob, qf(el.ob, el.part));
                col[i] = td.mode == Tuples::Mode::Plain ? p : td.scan_index[p];
            } else {
                Key k;
                for (std::size_t n = 0; n < qd.nodes().size(); ++n) {
                    QueryElement el = qd.locate_node(n);
                    if (!el.is_value) {
                        k.push_back(Value::integer(tc.part(i, el.ob, qf(el.ob, el.part))));
                    } else if (el.value.is_var()) {
                        Value v = qf.var(el.type, el.value.var_index());
                        k.push_back(v.is_var() ? tc.var(i, el.type, v.var_index()) : v);
                    } else {
                        k.push_back(el.value);
                    }
                }
                if (auto found = find_tuple(qd, td, k)) {
                    col[i] = *found;
                }
            }
        }
        y.set_column(fh, col);
    }
}

// The attribute columns of Δ_F(X): a constant, a value of the tuple, or a path's value.
void migrate_attrs(const SchemaMap& f, const ACSet& x, MigratedState& out) {
    const schema::Schema& t = *f.target();
    ACSet& y = out.state;
    for (std::uint32_t a = 0; a < t.num_attrs(); ++a) {
        AttrId fa(a);
        ObId c = t.attr(fa).dom;
        const Tuples& tc = *out.tuples[c.index()];
        const AttrImage& im = f.attr_image(fa);
        if (tc.count == 0 || im.kind == AttrImage::Kind::None) {
            continue; // add_parts left the column unset
        }
        std::vector<Value> col;
        switch (im.kind) {
        case AttrImage::Kind::None:
            break;
        case AttrImage::Kind::Constant:
            col.assign(tc.count, im.constant);
            break;
        case AttrImage::Kind::Value:
            if (im.value.is_var()) {
                col.resize(tc.count);
                for (std::size_t i = 0; i < tc.count; ++i) {
                    col[i] = tc.var(i, im.type, im.value.var_index());
                }
            } else {
                col.assign(tc.count, im.value);
            }
            break;
        case AttrImage::Kind::Path: {
            std::span<const Value> from = x.column(im.attr);
            if (tc.mode == Tuples::Mode::Plain && im.homs.empty()) {
                // Tuples are X's parts: the attribute's column, copied straight across.
                CATPLAN_ASSERT(from.size() == tc.count,
                               "a delta attribute starts at the tuples' object");
                y.set_column(fa, from);
                continue;
            }
            col.resize(tc.count);
            if (tc.mode == Tuples::Mode::Plain) {
                std::vector<Part> parts = path_column(x, tc.count, im.homs);
                for (std::size_t i = 0; i < tc.count; ++i) {
                    col[i] = parts[i] == kNoPart ? Value() : from[parts[i]];
                }
                break;
            }
            for (std::size_t i = 0; i < tc.count; ++i) {
                Part p = follow(x, tc.part(i, im.start_ob, im.start), im.homs);
                if (p != kNoPart) {
                    col[i] = from[p];
                }
            }
            break;
        }
        }
        y.set_column(fa, col);
    }
}

} // namespace

MigratedState migrate_state(const SchemaMap& f, const ACSet& x) {
    CATPLAN_ASSERT(f.ok(), "migrate: the schema map is not finished without errors");
    const schema::Schema& t = *f.target();
    MigratedState out;
    out.state = ACSet(f.target());
    ACSet& y = out.state;
    out.tuples.resize(t.num_obs());
    // Variables: those of X's type T, for every T' sent to T.
    for (std::uint32_t i = 0; i < t.num_attr_types(); ++i) {
        if (auto src = f.attr_type_image(AttrTypeId(i))) {
            for (std::uint32_t j = 0; j < x.num_vars(*src); ++j) {
                y.add_var(AttrTypeId(i), x.var_name(*src, j));
            }
        }
    }
    // Tuples and parts; then every column is written whole with set_column.
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        const Query& q = f.query(ObId(c));
        auto tu = std::make_unique<Tuples>();
        if (q.is_empty()) {
            tu->mode = Tuples::Mode::Empty;
        } else if (q.is_plain()) {
            tu->mode = Tuples::Mode::Plain;
            tu->ob = q.nodes()[0].ob;
            tu->count = x.num_parts(tu->ob);
        } else if (!scan(q, x, *tu)) {
            general(q, x, *tu);
        }
        y.add_parts(ObId(c), tu->count);
        if (std::vector<Symbol> names = tuple_names(q, *tu, x); !names.empty()) {
            y.set_part_names(ObId(c), std::move(names));
        }
        out.tuples[c] = std::move(tu);
    }
    migrate_homs(f, x, out);
    migrate_attrs(f, x, out);
    return out;
}

ACSet migrate(const SchemaMap& f, const ACSet& x) {
    return std::move(migrate_state(f, x).state);
}

Result<ACSetMorphism> migrate(const SchemaMap& f, const ACSetMorphism& alpha,
                              const MigratedState& x, const MigratedState& y) {
    const schema::Schema& t = *f.target();
    ACSetMorphism out;
    out.components.resize(t.num_obs());
    out.var_components.resize(t.num_attr_types());
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        const Query& q = f.query(ObId(c));
        const Tuples& tx = *x.tuples[c];
        const Tuples& ty = *y.tuples[c];
        auto& comp = out.components[c];
        comp.resize(tx.count);
        if (tx.mode == Tuples::Mode::Plain) {
            const auto& src = alpha.components[tx.ob.index()];
            std::copy_n(src.begin(), tx.count, comp.begin());
            continue;
        }
        for (std::size_t i = 0; i < tx.count; ++i) {
            Key k;
            k.reserve(q.nodes().size());
            for (std::size_t n = 0; n < q.nodes().size(); ++n) {
                QueryElement el = q.locate_node(n);
                if (!el.is_value) {
                    k.push_back(Value::integer(alpha(el.ob, tx.part(i, el.ob, el.part))));
                } else {
                    Value v =
                        el.value.is_var() ? tx.var(i, el.type, el.value.var_index()) : el.value;
                    if (v.is_var()) {
                        v = alpha.var(el.type, v.var_index());
                    }
                    k.push_back(v);
                }
            }
            auto found = find_tuple(q, ty, k);
            if (!found) {
                return fail("tuple " + x.state.part_label(ObId(c), static_cast<Part>(i)) + " of '" +
                            t.ob(ObId(c)).name +
                            "' has no image: the morphism does not preserve its query");
            }
            comp[i] = *found;
        }
    }
    for (std::uint32_t i = 0; i < t.num_attr_types(); ++i) {
        if (auto src = f.attr_type_image(AttrTypeId(i))) {
            out.var_components[i] = alpha.var_components[src->index()];
        }
    }
    return out;
}

Result<ACSetMorphism> migrate(const SchemaMap& f, const ACSetMorphism& alpha, const ACSet& x,
                              const ACSet& y) {
    return migrate(f, alpha, migrate_state(f, x), migrate_state(f, y));
}

namespace {

Result<rewrite::AttrExpr> translate_expr(const SchemaMap& f, const rewrite::AttrExpr& e) {
    rewrite::AttrExpr out = e;
    if (e.op == rewrite::AttrExpr::Op::Input) {
        bool found = false;
        for (std::uint32_t i = 0; i < f.target()->num_attr_types() && !found; ++i) {
            if (f.attr_type_image(AttrTypeId(i)) == e.input_type) {
                out.input_type = AttrTypeId(i);
                found = true;
            }
        }
        if (!found) {
            return fail("an expression reads a value of type '" +
                        f.source()->attr_type(e.input_type).name +
                        "', which no target attribute type is sent to");
        }
    }
    out.args.clear();
    for (const auto& a : e.args) {
        auto r = translate_expr(f, a);
        if (!r) {
            return fail(r.error());
        }
        out.args.push_back(std::move(*r));
    }
    return out;
}

/// An argument of an action or cost term of rule, on the migrated rule's parameters: a parameter
/// the first migrated one of its name; nullopt when the migration lost it.
std::optional<rewrite::ActionOf::Argument>
migrated_argument(const rewrite::Rule& rule, const rewrite::ActionOf::Argument& a,
                  const std::vector<rewrite::Parameter>& migrated) {
    if (a.parameter < 0) {
        return a;
    }
    const std::string& name = rule.parameters[static_cast<std::size_t>(a.parameter)].name;
    auto it = std::find_if(migrated.begin(), migrated.end(),
                           [&](const rewrite::Parameter& p) { return p.name == name; });
    if (it == migrated.end()) {
        return std::nullopt;
    }
    return rewrite::ActionOf::Argument{static_cast<int>(it - migrated.begin()), {}};
}

/// The action a migrated rule carries out: the source rule's on the migrated parameters; nullopt
/// (the rule's own name) when a parameter the action names is lost, since a step could not say
/// it.
std::optional<rewrite::ActionOf> migrated_action(const rewrite::Rule& rule,
                                                 const std::vector<rewrite::Parameter>& migrated) {
    if (!rule.action) {
        return std::nullopt;
    }
    rewrite::ActionOf out{rule.action->name, {}};
    for (const auto& a : rule.action->arguments) {
        auto m = migrated_argument(rule, a, migrated);
        if (!m) {
            return std::nullopt;
        }
        out.arguments.push_back(std::move(*m));
    }
    return out;
}

/// The migrated action costs what the source action costs: the same constant and the same
/// functions of the same arguments. A term whose argument the migration lost keeps it unresolved
/// (no value: a search that sums costs does not take the step).
std::optional<rewrite::Cost> migrated_cost(const rewrite::Rule& rule,
                                           const std::vector<rewrite::Parameter>& migrated) {
    if (!rule.cost) {
        return std::nullopt;
    }
    rewrite::Cost out{rule.cost->constant, {}};
    for (const auto& t : rule.cost->terms) {
        rewrite::Cost::Term term{t.function, {}};
        for (const auto& a : t.arguments) {
            term.arguments.push_back(
                migrated_argument(rule, a, migrated).value_or(rewrite::ActionOf::Argument{}));
        }
        out.terms.push_back(std::move(term));
    }
    return out;
}

} // namespace

std::vector<ObId> migrate_relations(const SchemaMap& f, const std::vector<ObId>& relations) {
    const schema::Schema& t = *f.target();
    const schema::Schema& s = *f.source();
    std::vector<ObId> out;
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        const Query& q = f.query(ObId(c));
        if (!q.is_plain() ||
            std::find(relations.begin(), relations.end(), q.nodes()[0].ob) == relations.end()) {
            continue;
        }
        ObId d = q.nodes()[0].ob;
        std::vector<HomId> covered;
        bool ok = true;
        for (std::uint32_t g = 0; g < t.num_homs() && ok; ++g) {
            if (t.hom(HomId(g)).dom != ObId(c)) {
                continue;
            }
            const auto& path = f.hom_image(HomId(g)).path;
            ok = path && path->size() == 1;
            if (ok) {
                covered.push_back(path->front());
            }
        }
        for (std::uint32_t h = 0; h < s.num_homs() && ok; ++h) {
            ok = s.hom(HomId(h)).dom != d ||
                 std::find(covered.begin(), covered.end(), HomId(h)) != covered.end();
        }
        for (std::uint32_t a = 0; a < s.num_attrs() && ok; ++a) {
            ok = s.attr(AttrId(a)).dom != d;
        }
        if (ok) {
            out.push_back(ObId(c));
        }
    }
    return out;
}

Result<rewrite::Rule> migrate(const SchemaMap& f, const rewrite::Rule& rule) {
    const schema::Schema& t = *f.target();
    rewrite::Rule out(f.target());
    out.name = rule.name;
    out.range = rule.range;
    MigratedState l = migrate_state(f, rule.L);
    MigratedState k = migrate_state(f, rule.K);
    MigratedState r = migrate_state(f, rule.R);
    auto lm = migrate(f, rule.l, k, l);
    if (!lm) {
        return fail("the left leg of '" + rule.name + "': " + lm.error());
    }
    auto rm = migrate(f, rule.r, k, r);
    if (!rm) {
        return fail("the right leg of '" + rule.name + "': " + rm.error());
    }
    out.l = std::move(*lm);
    out.r = std::move(*rm);
    for (const auto& cond : rule.conditions) {
        MigratedState n = migrate_state(f, cond.n_state);
        auto nm = migrate(f, cond.n, l, n);
        if (!nm) {
            return fail("condition '" + cond.name + "' of '" + rule.name + "': " + nm.error());
        }
        out.conditions.push_back(
            {cond.name, cond.negative, std::move(n.state), std::move(*nm), cond.range});
    }
    // Parameters: the tuples whose first object variable is the parameter's part.
    for (const auto& p : rule.parameters) {
        for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
            const Query& q = f.query(ObId(c));
            auto n = q.first_object_node();
            if (!n || q.nodes()[*n].ob != p.ob) {
                continue;
            }
            QueryElement el = q.locate_node(*n);
            const Tuples& tu = *l.tuples[c];
            for (std::size_t i = 0; i < tu.count; ++i) {
                if (tu.part(i, el.ob, el.part) == p.part) {
                    out.parameters.push_back({p.name, ObId(c), static_cast<Part>(i)});
                    break;
                }
            }
        }
    }
    out.action = migrated_action(rule, out.parameters);
    out.cost = migrated_cost(rule, out.parameters);
    out.relations = migrate_relations(f, rule.relations);
    // Expressions, per variable of R, carried to every target type sent to their type.
    out.exprs.assign(t.num_attr_types(), {});
    for (std::uint32_t i = 0; i < t.num_attr_types(); ++i) {
        auto src = f.attr_type_image(AttrTypeId(i));
        out.exprs[i].resize(r.state.num_vars(AttrTypeId(i)));
        if (!src || src->index() >= rule.exprs.size()) {
            continue;
        }
        const auto& from = rule.exprs[src->index()];
        for (std::size_t j = 0; j < from.size() && j < out.exprs[i].size(); ++j) {
            if (from[j]) {
                auto e = translate_expr(f, *from[j]);
                if (!e) {
                    return fail("an expression of '" + rule.name + "': " + e.error());
                }
                out.exprs[i][j] = std::move(*e);
            }
        }
    }
    out.L = std::move(l.state);
    out.K = std::move(k.state);
    out.R = std::move(r.state);
    return out;
}

Result<ACSetMorphism> migrate_match(const SchemaMap& f, const rewrite::Rule& rule,
                                    const ACSetMorphism& m, const ACSet& x) {
    return migrate(f, m, rule.L, x);
}

std::optional<TupleOrigins> tuple_origins(const SchemaMap& f, const MigratedState& x, ObId c) {
    const Query& q = f.query(c);
    auto n = q.first_object_node();
    if (!n) {
        return std::nullopt;
    }
    QueryElement el = q.locate_node(*n);
    const Tuples& tu = *x.tuples[c.index()];
    TupleOrigins out{el.ob, {}};
    out.parts.reserve(tu.count);
    for (std::size_t i = 0; i < tu.count; ++i) {
        out.parts.push_back(tu.part(i, el.ob, el.part));
    }
    return out;
}

} // namespace catplan::migrate
