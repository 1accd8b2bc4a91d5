#include "catplan/report/explain.hpp"

#include "catplan/migrate/migration.hpp"
#include "catplan/transfer/terms.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace catplan::report {

namespace {

using acset::ACSet;
using migrate::Query;
using migrate::SchemaMap;
using schema::GeneratorKind;
using schema::Schema;

// Which source generators some image uses, by kind.
struct Used {
    std::vector<bool> obs, homs, attr_types, attrs;

    explicit Used(const Schema& s)
        : obs(s.num_obs()),
          homs(s.num_homs()),
          attr_types(s.num_attr_types()),
          attrs(s.num_attrs()) {}

    void path(const std::vector<HomId>& homs_used) {
        for (HomId h : homs_used) {
            homs[h.index()] = true;
        }
    }
};

// A query uses every source object its shape has parts of, every hom and attribute set in its
// shape, and the attribute types of its value variables.
void mark_query(const Query& q, Used& used) {
    const Schema& s = *q.source();
    const ACSet& shape = q.state();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < shape.num_parts(ob); ++p) {
            used.obs[o] = true;
            for (HomId h : s.homs_from(ob)) {
                if (shape.subpart(h, p) != kNoPart) {
                    used.homs[h.index()] = true;
                }
            }
            for (AttrId a : s.attrs_from(ob)) {
                if (!shape.subpart(a, p).is_unset()) {
                    used.attrs[a.index()] = true;
                    used.attr_types[s.attr(a).codom.index()] = true;
                }
            }
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        if (shape.num_vars(AttrTypeId(t)) > 0) {
            used.attr_types[t] = true;
        }
    }
}

void mark_attr(const SchemaMap& f, AttrId a, Used& used) {
    const auto& image = f.attr_image(a);
    const Schema& s = *f.source();
    if (image.kind == migrate::AttrImage::Kind::Path) {
        used.path(image.homs);
        used.attrs[image.attr.index()] = true;
        used.attr_types[s.attr(image.attr).codom.index()] = true;
    } else if (image.kind == migrate::AttrImage::Kind::Value) {
        used.attr_types[image.type.index()] = true;
    }
}

Used used_generators(const SchemaMap& f) {
    const Schema& t = *f.target();
    Used used(*f.source());
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        mark_query(f.query(ObId(c)), used);
    }
    for (std::uint32_t h = 0; h < t.num_homs(); ++h) {
        if (const auto& path = f.hom_image(HomId(h)).path) {
            used.path(*path);
        }
    }
    for (std::uint32_t a = 0; a < t.num_attr_types(); ++a) {
        if (auto image = f.attr_type_image(AttrTypeId(a))) {
            used.attr_types[image->index()] = true;
        }
    }
    for (std::uint32_t a = 0; a < t.num_attrs(); ++a) {
        mark_attr(f, AttrId(a), used);
    }
    return used;
}

// The statements of x about part p (of the source object the query's tuple starts at) that
// the query asks for: the homs and attributes its shape sets at its first object variable.
std::vector<std::string> asked_statements(const Query& q, const ACSet& x, Part p) {
    std::vector<std::string> out;
    auto node = q.first_object_node();
    if (!node || q.is_plain()) {
        return out;
    }
    const Schema& s = *q.source();
    const ACSet& shape = q.state();
    migrate::QueryElement at = q.locate_node(*node);
    for (HomId h : s.homs_from(at.ob)) {
        if (shape.subpart(h, at.part) != kNoPart) {
            out.push_back(transfer::hom_statement(x, h, p));
        }
    }
    for (AttrId a : s.attrs_from(at.ob)) {
        if (!shape.subpart(a, at.part).is_unset()) {
            out.push_back(transfer::attr_statement(x, a, p));
        }
    }
    return out;
}

// "a", "a and b", "a, b and c".
std::string and_list(const std::vector<std::string>& items) {
    if (items.size() <= 1) {
        return items.empty() ? std::string() : items.front();
    }
    std::vector<std::string> head(items.begin(), items.end() - 1);
    return fmt::format("{} and {}", fmt::join(head, ", "), items.back());
}

// The parts of a side of the rule (L or R) through m: those `changed` lists (deleted_parts or
// created_parts) as `css_class`, the others, which K keeps, as "matched".
std::vector<dot::PartClass> marks(const ACSet& side, const hom::ACSetMorphism& m,
                                  const std::vector<std::vector<Part>>& changed,
                                  const char* css_class) {
    std::vector<dot::PartClass> out;
    if (m.components.empty()) {
        return out; // no morphism was kept
    }
    for (std::uint32_t o = 0; o < side.schema().num_obs(); ++o) {
        const auto& gone = changed[o];
        for (Part q = 0; q < side.num_parts(ObId(o)); ++q) {
            bool c = std::find(gone.begin(), gone.end(), q) != gone.end();
            out.push_back({ObId(o), m.components[o][q], c ? css_class : "matched"});
        }
    }
    return out;
}

} // namespace

MapSummary summarize_map(const SchemaMap& f) {
    MapSummary out;
    for (auto& line : migrate::describe_map(f)) {
        if (line.target.kind == GeneratorKind::Ob) {
            out.objects.push_back(std::move(line));
        }
    }
    const Schema& s = *f.source();
    Used used = used_generators(f);
    auto lost = [&](GeneratorKind kind, const std::vector<bool>& flags, auto name_of) {
        for (std::uint32_t i = 0; i < flags.size(); ++i) {
            if (!flags[i]) {
                out.lost.push_back({{kind, i}, name_of(i)});
            }
        }
    };
    lost(GeneratorKind::Ob, used.obs, [&](std::uint32_t i) { return s.ob(ObId(i)).name; });
    lost(GeneratorKind::Hom, used.homs, [&](std::uint32_t i) { return s.hom(HomId(i)).name; });
    lost(GeneratorKind::AttrType, used.attr_types,
         [&](std::uint32_t i) { return s.attr_type(AttrTypeId(i)).name; });
    lost(GeneratorKind::Attr, used.attrs, [&](std::uint32_t i) { return s.attr(AttrId(i)).name; });
    return out;
}

std::string lost_names(const MapSummary& s, GeneratorKind kind) {
    std::vector<std::string> names;
    for (const auto& g : s.lost) {
        if (g.source.kind == kind) {
            names.push_back(g.name);
        }
    }
    return fmt::format("{}", fmt::join(names, ", "));
}

std::vector<std::string> binding_reasons(const SchemaMap& f, const rewrite::Rule& source_rule,
                                         const rewrite::Rule& target_rule,
                                         const transfer::StepTransfer& step, const ACSet& x,
                                         const ACSet& y) {
    // (source part, line), grouped by source part at the end so a part's reasons read together.
    std::vector<std::pair<std::string, std::string>> found;
    if (step.kind != transfer::StepTransfer::Kind::Generated) {
        return {};
    }
    auto lines = migrate::describe_map(f); // the objects first, in the target schema's order
    auto add = [&](Part in_x, ObId source_ob, ObId ob, Part in_y) {
        auto facts = asked_statements(f.query(ob), x, in_x);
        if (facts.empty()) {
            facts.push_back(transfer::part_statement(x, source_ob, in_x));
        }
        std::string from = transfer::part_word(x, source_ob, in_x);
        // A target part known only by its label or a made-up name (the hand-empty block's
        // Receptacle) is named by its object alone: such a name means nothing to a person.
        std::string to = transfer::has_readable_word(y, ob, in_y)
                             ? transfer::part_statement(y, ob, in_y)
                             : "a " + lines[ob.index()].name;
        std::pair<std::string, std::string> item{
            from, fmt::format("{} ↦ {} because {} and {} ⇒ {}", from, to, and_list(facts),
                              lines[ob.index()].name, lines[ob.index()].image)};
        if (std::find(found.begin(), found.end(), item) == found.end()) {
            found.push_back(std::move(item));
        }
    };
    auto migrated_l = migrate::migrate_state(f, source_rule.L);
    const Schema& t = *f.target();
    for (std::uint32_t c = 0; c < t.num_obs(); ++c) {
        ObId ob(c);
        auto origin = migrate::tuple_origins(f, migrated_l, ob);
        if (!origin) {
            continue;
        }
        for (Part p = 0; p < target_rule.L.num_parts(ob) && p < origin->parts.size(); ++p) {
            Part in_x = step.source_match.components[origin->ob.index()][origin->parts[p]];
            Part in_y = step.target_match.components[c][p];
            add(in_x, origin->ob, ob, in_y);
            // A bound part is often also a part of a more specific object the rule does not
            // mention (Object E is BreadSliced E): that is the map's reading of the source part.
            for (HomId h : t.homs_into(ob)) {
                ObId d = t.hom(h).dom;
                const Query& q = f.query(d);
                auto node = q.first_object_node();
                if (q.is_plain() || !node || q.nodes()[*node].ob != origin->ob) {
                    continue;
                }
                for (Part z = 0; z < y.num_parts(d); ++z) {
                    if (y.subpart(h, z) == in_y) {
                        add(in_x, origin->ob, d, z);
                    }
                }
            }
        }
    }
    std::vector<std::string> order; // source parts in the order first met
    for (const auto& [from, line] : found) {
        if (std::find(order.begin(), order.end(), from) == order.end()) {
            order.push_back(from);
        }
    }
    std::vector<std::string> out;
    for (const auto& from : order) {
        for (const auto& item : found) {
            if (item.first == from) {
                out.push_back(item.second);
            }
        }
    }
    return out;
}

StepMarks step_marks(const rewrite::Rule* source_rule, const rewrite::Rule* target_rule,
                     const transfer::StepTransfer& step) {
    StepMarks out;
    auto side = [](const rewrite::Rule& r, const hom::ACSetMorphism& match,
                   const hom::ACSetMorphism& comatch, std::vector<dot::PartClass>& before,
                   std::vector<dot::PartClass>& after) {
        std::vector<std::vector<Part>> deleted, created;
        for (std::uint32_t o = 0; o < r.L.schema().num_obs(); ++o) {
            deleted.push_back(r.deleted_parts(ObId(o)));
            created.push_back(r.created_parts(ObId(o)));
        }
        before = marks(r.L, match, deleted, "deleted");
        after = marks(r.R, comatch, created, "created");
    };
    if (source_rule != nullptr) {
        side(*source_rule, step.source_match, step.source_comatch, out.source_before,
             out.source_after);
    }
    if (target_rule != nullptr && step.kind == transfer::StepTransfer::Kind::Generated) {
        side(*target_rule, step.target_match, step.target_comatch, out.target_before,
             out.target_after);
    }
    return out;
}

std::vector<UniformValues> uniform_values(const ACSet& x) {
    std::vector<UniformValues> out;
    const Schema& s = x.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        const auto attrs = s.attrs_from(ob);
        if (x.num_parts(ob) == 0 || attrs.empty()) {
            continue;
        }
        UniformValues u{ob, {}};
        for (AttrId a : attrs) {
            const auto& first = x.subpart(a, 0);
            bool same = !first.is_unset() && !first.is_var();
            for (Part p = 1; same && p < x.num_parts(ob); ++p) {
                same = x.subpart(a, p) == first;
            }
            if (!same) {
                break;
            }
            u.values.push_back(
                fmt::format("{} = {}", s.attr(a).name, x.value_label(s.attr(a).codom, first)));
        }
        if (u.values.size() == attrs.size()) {
            out.push_back(std::move(u));
        }
    }
    return out;
}

std::vector<dot::PartLabel> readable_labels(const ACSet& x) {
    std::vector<dot::PartLabel> out;
    const Schema& s = x.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            auto words = transfer::part_words(x, ob, p);
            if (transfer::is_user_name(words.front())) {
                continue;
            }
            std::string label = words.size() > 1 ? words.front() : "a " + s.ob(ob).name;
            if (label != x.part_label(ob, p)) {
                out.push_back({ob, p, std::move(label)});
            }
        }
    }
    return out;
}

} // namespace catplan::report
