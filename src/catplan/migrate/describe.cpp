#include "catplan/migrate/describe.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>

namespace catplan::migrate {
namespace {

using acset::ACSet;
using schema::Schema;

// Labels for a query's shape: its nodes' names where a node lands, else the shape's labels.
struct ShapeLabels {
    const Query& q;
    std::map<std::pair<std::uint32_t, Part>, std::string> parts;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> vars;

    explicit ShapeLabels(const Query& query) : q(query) {
        for (std::size_t i = 0; i < q.nodes().size(); ++i) {
            QueryElement el = q.locate_node(i);
            if (!el.is_value) {
                parts.emplace(std::pair{el.ob.index(), el.part}, q.nodes()[i].name);
            } else if (el.value.is_var()) {
                vars.emplace(std::pair{el.type.index(), el.value.var_index()}, q.nodes()[i].name);
            }
        }
    }

    std::string part(ObId ob, Part p) const {
        auto it = parts.find({ob.index(), p});
        return it != parts.end() ? it->second : q.state().part_label(ob, p);
    }

    std::string value(AttrTypeId t, const acset::Value& v) const {
        if (v.is_var()) {
            auto it = vars.find({t.index(), v.var_index()});
            if (it != vars.end()) {
                return it->second;
            }
        }
        return q.state().value_label(t, v);
    }
};

// "on_l⋅isOn" for a path of source homs ("id" for the empty path).
std::string path_words(const Schema& s, const std::vector<HomId>& homs) {
    if (homs.empty()) {
        return "id";
    }
    std::vector<std::string> names;
    for (HomId h : homs) {
        names.push_back(s.hom(h).name);
    }
    return fmt::format("{}", fmt::join(names, "⋅"));
}

std::string describe_hom(const SchemaMap& f, HomId h) {
    const HomImage& image = f.hom_image(h);
    if (image.path) {
        return path_words(*f.source(), *image.path);
    }
    if (!image.morphism) {
        return "(none)";
    }
    // A query morphism Q_d' -> Q_c': where each part of the codomain's shape goes.
    const auto& t = *f.target();
    const Query& qfrom = f.query(t.hom(h).codom);
    const Query& qto = f.query(t.hom(h).dom);
    const ACSet& from = qfrom.state();
    ShapeLabels from_label(qfrom), to_label(qto);
    std::vector<std::string> items;
    for (std::uint32_t o = 0; o < from.schema().num_obs(); ++o) {
        for (Part p = 0; p < from.num_parts(ObId(o)); ++p) {
            items.push_back(fmt::format("{} ↦ {}", from_label.part(ObId(o), p),
                                        to_label.part(ObId(o), image.morphism->components[o][p])));
        }
    }
    return fmt::format("{}", fmt::join(items, ", "));
}

std::string describe_attr(const SchemaMap& f, AttrId a) {
    const AttrImage& image = f.attr_image(a);
    const auto& s = *f.source();
    switch (image.kind) {
    case AttrImage::Kind::Constant:
        return fmt::format("x -> {}", image.constant.to_string());
    case AttrImage::Kind::Value:
        return image.value.to_string();
    case AttrImage::Kind::Path: {
        auto homs = image.homs;
        std::string path = homs.empty() ? s.attr(image.attr).name
                                        : path_words(s, homs) + "⋅" + s.attr(image.attr).name;
        return path;
    }
    case AttrImage::Kind::None:
        break;
    }
    return "(none)";
}

} // namespace

std::string describe_query(const Query& q) {
    const auto& s = *q.source();
    if (q.is_empty()) {
        return "@empty";
    }
    if (q.is_plain()) {
        return s.ob(q.nodes()[0].ob).name;
    }
    const ACSet& shape = q.state();
    ShapeLabels label(q);
    std::vector<std::string> parts, facts;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < shape.num_parts(ob); ++p) {
            parts.push_back(fmt::format("{}::{}", label.part(ob, p), s.ob(ob).name));
            for (HomId h : s.homs_from(ob)) {
                Part v = shape.subpart(h, p);
                if (v != kNoPart) {
                    facts.push_back(fmt::format("{}({}) == {}", s.hom(h).name, label.part(ob, p),
                                                label.part(s.hom(h).codom, v)));
                }
            }
            for (AttrId a : s.attrs_from(ob)) {
                const auto& v = shape.subpart(a, p);
                if (!v.is_unset()) {
                    facts.push_back(fmt::format("{}({}) == {}", s.attr(a).name, label.part(ob, p),
                                                label.value(s.attr(a).codom, v)));
                }
            }
        }
    }
    if (parts.empty()) {
        return "@unit";
    }
    return facts.empty()
               ? fmt::format("{{{}}}", fmt::join(parts, ", "))
               : fmt::format("{{{} | {}}}", fmt::join(parts, ", "), fmt::join(facts, ", "));
}

std::vector<MapLine> describe_map(const SchemaMap& f) {
    const auto& t = *f.target();
    std::vector<MapLine> out;
    using schema::GeneratorKind;
    for (std::uint32_t i = 0; i < t.num_obs(); ++i) {
        out.push_back(
            {{GeneratorKind::Ob, i}, t.ob(ObId(i)).name, describe_query(f.query(ObId(i)))});
    }
    for (std::uint32_t i = 0; i < t.num_homs(); ++i) {
        out.push_back({{GeneratorKind::Hom, i}, t.hom(HomId(i)).name, describe_hom(f, HomId(i))});
    }
    for (std::uint32_t i = 0; i < t.num_attr_types(); ++i) {
        auto src = f.attr_type_image(AttrTypeId(i));
        std::string image = src ? f.source()->attr_type(*src).name
                                : std::string(schema::to_string(f.attr_type_kind(AttrTypeId(i))));
        out.push_back({{GeneratorKind::AttrType, i}, t.attr_type(AttrTypeId(i)).name, image});
    }
    for (std::uint32_t i = 0; i < t.num_attrs(); ++i) {
        out.push_back(
            {{GeneratorKind::Attr, i}, t.attr(AttrId(i)).name, describe_attr(f, AttrId(i))});
    }
    return out;
}

} // namespace catplan::migrate
