#include "catplan/pddl/detail/export_model.hpp"

#include "catplan/base/ascii.hpp"
#include "catplan/base/union_find.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace catplan::pddl::detail {

std::string pddl_name(std::string_view s, std::string_view fallback) {
    std::string out;
    for (char c : s) {
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    }
    if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) {
        out = std::string(fallback) + out;
    }
    return out;
}

bool NameSet::taken(std::string_view name) const {
    return lowered_.count(ascii_lowercase(name)) != 0;
}

std::string NameSet::take(std::string_view want) {
    std::string name(want);
    for (int k = 2; taken(name); ++k) {
        name = fmt::format("{}_{}", want, k);
    }
    lowered_.insert(ascii_lowercase(name));
    return name;
}

const std::string& Reading::arg_type(ObId ob) const {
    const Component& c = components[component[ob.index()]];
    return c.forest ? type_of_ob[ob.index()] : c.type_name;
}

bool Reading::is_a(HomId f) const {
    const auto& h = schema->hom(f);
    return entity[h.dom.index()] && entity[h.codom.index()];
}

namespace {

/// The is-a components of the entity objects, in declaration order.
void find_components(Reading& r) {
    const Schema& s = *r.schema;
    UnionFind uf(s.num_obs());
    for (std::uint32_t f = 0; f < s.num_homs(); ++f) {
        if (r.is_a(HomId(f))) {
            uf.union_sets(s.hom(HomId(f)).dom.index(), s.hom(HomId(f)).codom.index());
        }
    }
    std::map<std::uint32_t, std::size_t> index;
    r.component.assign(s.num_obs(), 0);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!r.entity[o]) {
            continue;
        }
        auto [it, fresh] = index.emplace(uf.find(o), r.components.size());
        if (fresh) {
            r.components.emplace_back();
        }
        r.component[o] = it->second;
        Component& c = r.components[it->second];
        c.obs.push_back(ObId(o));
        std::size_t up = 0;
        for (HomId f : s.homs_from(ObId(o))) {
            up += r.is_a(f) ? 1 : 0;
            if (r.is_a(f)) {
                r.parent[o] = f;
            }
        }
        c.forest = c.forest && up <= 1;
    }
}

/// Every concrete value of attribute a in x, by display form.
void collect_values(const ACSet& x, AttrId a, std::set<std::string>& out) {
    for (Part p = 0; p < x.num_parts(x.schema().attr(a).dom); ++p) {
        if (x.subpart(a, p).is_concrete()) {
            out.insert(x.subpart(a, p).to_string());
        }
    }
}

/// Whether x reads attribute a as a pattern does: a concrete value, or a variable held by two
/// cells (of any attribute of the same type).
bool reads(const ACSet& x, AttrId a) {
    const Schema& s = x.schema();
    for (Part p = 0; p < x.num_parts(s.attr(a).dom); ++p) {
        const auto& v = x.subpart(a, p);
        if (v.is_concrete() ||
            (v.is_var() && x.var_incident(s.attr(a).codom, v.var_index()).size() > 1)) {
            return true;
        }
    }
    return false;
}

/// The patterns of the domain and problem: each rule's L and conditions, and the goal.
std::vector<const ACSet*> patterns(const plan::Domain& d, const plan::Problem* p) {
    std::vector<const ACSet*> out;
    for (const auto& r : d.rules) {
        out.push_back(&r->L);
        for (const auto& c : r->conditions) {
            out.push_back(&c.n_state);
        }
    }
    if (p != nullptr) {
        out.push_back(p->goal.get());
    }
    return out;
}

void read_attrs(Reading& r, const plan::Domain& d, const plan::Problem* p, NameSet& names) {
    const Schema& s = *r.schema;
    r.attrs.resize(s.num_attrs());
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        AttrId a(i);
        const auto& info = s.attr(a);
        const auto& type = s.attr_type(info.codom);
        AttrReading& ar = r.attrs[i];
        if (type.kind == schema::ValueKind::Bool && r.entity[info.dom.index()]) {
            ar.use = AttrUse::Bool;
            ar.predicate = names.take(pddl_name(info.name, "p"));
            continue;
        }
        if (type.name == "Name") {
            ar.use = AttrUse::Name;
            continue;
        }
        auto pats = patterns(d, p);
        bool read =
            std::any_of(pats.begin(), pats.end(), [&](const ACSet* x) { return reads(*x, a); });
        if (!read) {
            ar.use = AttrUse::Dropped;
            r.notes.push_back(fmt::format("the attribute {} ({}) is left out: no rule and no goal "
                                          "reads it, so no plan depends on it",
                                          info.name, type.name));
            continue;
        }
        std::set<std::string> values;
        for (const auto& rule : d.rules) {
            collect_values(rule->L, a, values);
            collect_values(rule->R, a, values);
            for (const auto& c : rule->conditions) {
                collect_values(c.n_state, a, values);
            }
        }
        if (p != nullptr) {
            collect_values(*p->initial, a, values);
            collect_values(*p->goal, a, values);
        }
        ar.use = AttrUse::Values;
        NameSet fact_values; // distinct values, distinct names
        for (const auto& v : values) {
            std::string text = v.size() >= 2 && v.front() == '"' ? v.substr(1, v.size() - 2) : v;
            // A fact's value is part of its predicate's name (export_writer.hpp), else its own
            // unary predicate.
            ar.value_predicate[v] = r.entity[info.dom.index()]
                                        ? names.take(pddl_name(info.name + "_" + text, "p"))
                                        : fact_values.take(pddl_name(text, "v"));
        }
    }
}

} // namespace

Result<Reading> read_schema(const plan::Domain& domain, const plan::Problem* problem,
                            NameSet& names) {
    const Schema& s = *domain.schema;
    Reading r;
    r.schema = &s;
    r.entity.assign(s.num_obs(), false);
    r.parent.resize(s.num_obs());
    for (std::uint32_t f = 0; f < s.num_homs(); ++f) {
        r.entity[s.hom(HomId(f)).codom.index()] = true;
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        ObId ob = s.attr(AttrId(a)).dom;
        // An object that nothing points into and that points somewhere is a fact with attribute
        // values when it points to one thing (the sandwich kitchen's BreadSliced, the slides'
        // IsClear: a unary predicate) or when a rule creates or deletes its parts on their own;
        // else a part of the things it points to (the Kitchenworld's BreadSliced, an Object and
        // a Receptacle). The importer's types, which carry a Name attribute, stay types.
        bool named_type =
            std::any_of(s.attrs_from(ob).begin(), s.attrs_from(ob).end(),
                        [&](AttrId x) { return s.attr_type(s.attr(x).codom).name == "Name"; });
        bool changed = std::any_of(domain.rules.begin(), domain.rules.end(), [&](const auto& rule) {
            return !rule->created_parts(ob).empty() || !rule->deleted_parts(ob).empty();
        });
        bool fact = s.homs_into(ob).empty() && !s.homs_from(ob).empty() &&
                    ((s.homs_from(ob).size() == 1 && !named_type) || changed);
        r.entity[ob.index()] = r.entity[ob.index()] || !fact;
    }
    find_components(r);
    r.type_of_ob.resize(s.num_obs());
    r.member_predicate.resize(s.num_obs());
    r.fact_predicate.resize(s.num_obs());
    NameSet types;
    types.take("object");
    for (auto& c : r.components) {
        if (!c.forest) {
            std::vector<std::string> roots; // the objects without an is-a hom
            for (ObId ob : c.obs) {
                if (std::none_of(s.homs_from(ob).begin(), s.homs_from(ob).end(),
                                 [&](HomId f) { return r.is_a(f); })) {
                    roots.push_back(pddl_name(s.ob(ob).name, "t"));
                }
            }
            c.type_name = types.take(fmt::format("{}", fmt::join(roots, "_or_")));
            for (ObId ob : c.obs) {
                r.member_predicate[ob.index()] = names.take("is_" + pddl_name(s.ob(ob).name, "t"));
            }
            continue;
        }
        for (ObId ob : c.obs) {
            std::string n = pddl_name(s.ob(ob).name, "t");
            r.type_of_ob[ob.index()] = n == "object" ? n : types.take(n);
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!r.entity[o]) {
            r.facts.push_back(ObId(o));
            r.fact_predicate[o] = names.take(pddl_name(s.ob(ObId(o)).name, "p"));
        }
    }
    read_attrs(r, domain, problem, names);
    return r;
}

std::string thing_type(const Reading& rd, const Thing& t) {
    const Component& c = rd.components[t.component];
    return c.forest ? rd.type_of_ob[t.bottom.index()] : c.type_name;
}

namespace {

/// The concrete name attribute of one of the thing's parts, if any.
std::optional<std::string> pin_of(const Reading& rd, const ACSet& x, const Thing& t) {
    const Schema& s = x.schema();
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        ObId ob = s.attr(AttrId(a)).dom;
        if (rd.attrs[a].use == AttrUse::Name && t.part[ob.index()] != kNoPart &&
            x.subpart(AttrId(a), t.part[ob.index()]).is_concrete()) {
            return std::string(x.subpart(AttrId(a), t.part[ob.index()]).as_string());
        }
    }
    return std::nullopt;
}

/// Fills the thing's shape, bottom and first object; fails when it is not a chain of a forest.
Result<bool> describe(const Reading& rd, const ACSet& x, Thing& t, std::string_view what) {
    const Schema& s = x.schema();
    std::vector<std::string> obs;
    std::vector<ObId> bottoms;
    bool first = true;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        Part p = t.part[o];
        if (p == kNoPart) {
            continue;
        }
        obs.push_back(s.ob(ObId(o)).name);
        if (first) {
            t.first = ObId(o);
            t.component = rd.component[o];
            first = false;
        }
        bool below = false;
        for (HomId f : s.homs_into(ObId(o))) {
            below = below || (rd.is_a(f) && !x.incident(f, p).empty());
        }
        if (!below) {
            bottoms.push_back(ObId(o));
        }
    }
    t.shape = fmt::format("{}", fmt::join(obs, "+"));
    if (bottoms.empty()) {
        return fail(fmt::format("not expressible: in {}, the is-a homs of a {} form a cycle", what,
                                t.shape));
    }
    if (rd.components[t.component].forest && bottoms.size() != 1) {
        return fail(fmt::format("not expressible: in {}, the parts {} of one thing are not a chain "
                                "of is-a homs (PDDL types form a tree)",
                                what, x.part_label(bottoms[0], t.part[bottoms[0].index()])));
    }
    t.bottom = bottoms.empty() ? t.first : bottoms[0];
    return true;
}

} // namespace

Result<Things> find_things(const Reading& rd, const ACSet& x,
                           const std::set<std::string>& marker_shapes, NameSet& names,
                           std::string_view what) {
    const Schema& s = x.schema();
    std::vector<std::size_t> offset(s.num_obs() + 1, 0);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        offset[o + 1] = offset[o] + (rd.entity[o] ? x.num_parts(ObId(o)) : 0);
    }
    UnionFind uf(offset.back());
    for (std::uint32_t f = 0; f < s.num_homs(); ++f) {
        const auto& h = s.hom(HomId(f));
        if (!rd.is_a(HomId(f))) {
            continue;
        }
        for (Part p = 0; p < x.num_parts(h.dom); ++p) {
            Part q = x.subpart(HomId(f), p);
            if (q != kNoPart) {
                uf.union_sets(static_cast<std::uint32_t>(offset[h.dom.index()] + p),
                              static_cast<std::uint32_t>(offset[h.codom.index()] + q));
            }
        }
    }
    Things out;
    out.of.resize(s.num_obs());
    std::map<std::uint32_t, std::size_t> index;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!rd.entity[o]) {
            continue;
        }
        out.of[o].resize(x.num_parts(ObId(o)));
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            auto [it, fresh] = index.emplace(uf.find(static_cast<std::uint32_t>(offset[o] + p)),
                                             out.things.size());
            if (fresh) {
                out.things.emplace_back();
                out.things.back().part.assign(s.num_obs(), kNoPart);
            }
            Thing& t = out.things[it->second];
            if (t.part[o] != kNoPart) {
                return fail(fmt::format("not expressible: in {}, {} and {} of {} are parts of one "
                                        "thing (glued by is-a homs)",
                                        what, x.part_label(ObId(o), t.part[o]),
                                        x.part_label(ObId(o), p), s.ob(ObId(o)).name));
            }
            t.part[o] = p;
            out.of[o][p] = it->second;
        }
    }
    for (auto& t : out.things) {
        if (auto ok = describe(rd, x, t, what); !ok) {
            return fail(ok.error());
        }
        if (auto pin = pin_of(rd, x, t)) {
            t.pinned = t.named = true;
            t.name = pddl_name(*pin, "o");
            names.take(t.name);
            continue;
        }
        for (std::uint32_t o = 0; o < s.num_obs() && !t.named; ++o) {
            if (t.part[o] != kNoPart && !x.part_name(ObId(o), t.part[o]).empty()) {
                t.named = true;
                t.name = pddl_name(x.part_name(ObId(o), t.part[o]), "o");
            }
        }
        if (!t.named && marker_shapes.count(t.shape) != 0) {
            t.marker = true;
            continue;
        }
        if (!t.named) {
            t.name = fmt::format("{}_{}", pddl_name(s.ob(t.first).name, "t"),
                                 t.part[t.first.index()] + 1);
        }
        if (names.taken(t.name)) {
            t.name += "_" + pddl_name(s.ob(t.first).name, "t");
        }
        t.name = names.take(t.name);
    }
    return out;
}

} // namespace catplan::pddl::detail
