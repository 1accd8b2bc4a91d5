#include "catplan/migrate/describe.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace catplan::migrate {
namespace {

using acset::ACSet;
using schema::Schema;

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
        return "(none: its domain's query is @empty)";
    }
    // A query morphism Q_d' -> Q_c': where each element of the codomain's shape goes.
    const auto& t = *f.target();
    const Query& qfrom = f.query(t.hom(h).codom);
    const Query& qto = f.query(t.hom(h).dom);
    const ACSet& from = qfrom.state();
    ShapeNames from_label(qfrom), to_label(qto);
    std::vector<std::string> items;
    for (std::uint32_t o = 0; o < from.schema().num_obs(); ++o) {
        for (Part p = 0; p < from.num_parts(ObId(o)); ++p) {
            items.push_back(fmt::format("{} ↦ {}", from_label.part(ObId(o), p),
                                        to_label.part(ObId(o), image.morphism->components[o][p])));
        }
    }
    for (std::uint32_t a = 0; a < from.schema().num_attr_types(); ++a) {
        AttrTypeId type(a);
        for (std::uint32_t j = 0;
             j < from.num_vars(type) && j < image.morphism->var_components[a].size(); ++j) {
            items.push_back(fmt::format("{} ↦ {}", from_label.value(type, acset::Value::var(j)),
                                        to_label.value(type, image.morphism->var(type, j))));
        }
    }
    if (items.empty()) {
        return "(the unique map into @unit)";
    }
    return fmt::format("{}", fmt::join(items, ", "));
}

// A term of a query in the notation of its facts: hasColor(on_l(o)), "purple".
std::string term_words(const Schema& s, const Term& t) {
    if (t.is_literal()) {
        return t.literal.to_string();
    }
    std::string out = t.var;
    for (HomId h : t.homs) {
        out = fmt::format("{}({})", s.hom(h).name, out);
    }
    return t.attr ? fmt::format("{}({})", s.attr(*t.attr).name, out) : out;
}

std::string describe_attr(const SchemaMap& f, AttrId a) {
    const AttrImage& image = f.attr_image(a);
    const auto& s = *f.source();
    const Query& q = f.query(f.target()->attr(a).dom);
    switch (image.kind) {
    case AttrImage::Kind::Constant:
        return fmt::format("x -> {}", image.constant.to_string());
    case AttrImage::Kind::Value: {
        // A query variable by its name, else a term that reaches the value.
        auto name = ShapeNames(q).variable(image.type, image.value);
        return name ? *name : term_words(s, q.witness_value(image.type, image.value));
    }
    case AttrImage::Kind::Path: {
        if (q.is_plain()) {
            return image.homs.empty() ? s.attr(image.attr).name
                                      : path_words(s, image.homs) + "⋅" + s.attr(image.attr).name;
        }
        // From an element of the query: a term of the query's variables.
        Term t = q.witness(image.start_ob, image.start);
        t.homs.insert(t.homs.end(), image.homs.begin(), image.homs.end());
        t.attr = image.attr;
        return term_words(s, t);
    }
    case AttrImage::Kind::None:
        break;
    }
    return "(none: its domain's query is @empty)";
}

} // namespace

ShapeNames::ShapeNames(const Query& q) : q_(q) {
    for (std::size_t i = 0; i < q.nodes().size(); ++i) {
        QueryElement el = q.locate_node(i);
        if (!el.is_value) {
            parts_.emplace_back(std::pair{el.ob.index(), el.part}, q.nodes()[i].name);
        } else if (el.value.is_var()) {
            vars_.emplace_back(std::pair{el.type.index(), el.value.var_index()}, q.nodes()[i].name);
        }
    }
}

std::string ShapeNames::part(ObId ob, Part p) const {
    for (const auto& [key, name] : parts_) {
        if (key == std::pair{ob.index(), p}) {
            return name;
        }
    }
    return q_.state().part_label(ob, p);
}

std::optional<std::string> ShapeNames::variable(AttrTypeId t, const acset::Value& v) const {
    if (v.is_var()) {
        for (const auto& [key, name] : vars_) {
            if (key == std::pair{t.index(), v.var_index()}) {
                return name;
            }
        }
    }
    return std::nullopt;
}

std::string ShapeNames::value(AttrTypeId t, const acset::Value& v) const {
    auto name = variable(t, v);
    return name ? *name : q_.state().value_label(t, v);
}

std::vector<std::string> query_facts(const Query& q, const ShapeNames& names) {
    const Schema& s = *q.source();
    const ACSet& shape = q.state();
    std::vector<std::string> facts;
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        ObId ob(i);
        for (Part p = 0; p < shape.num_parts(ob); ++p) {
            for (HomId h : s.homs_from(ob)) {
                Part v = shape.subpart(h, p);
                if (v != kNoPart) {
                    facts.push_back(fmt::format("{}({}) == {}", s.hom(h).name, names.part(ob, p),
                                                names.part(s.hom(h).codom, v)));
                }
            }
            for (AttrId a : s.attrs_from(ob)) {
                const acset::Value& v = shape.subpart(a, p);
                if (!v.is_unset()) {
                    facts.push_back(fmt::format("{}({}) == {}", s.attr(a).name, names.part(ob, p),
                                                names.value(s.attr(a).codom, v)));
                }
            }
        }
    }
    return facts;
}

std::string describe_query(const Query& q) {
    const auto& s = *q.source();
    if (q.is_empty()) {
        return "@empty";
    }
    if (q.is_plain()) {
        return s.ob(q.nodes()[0].ob).name;
    }
    const ACSet& shape = q.state();
    ShapeNames names(q);
    std::vector<std::string> elements;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < shape.num_parts(ObId(o)); ++p) {
            elements.push_back(fmt::format("{}::{}", names.part(ObId(o), p), s.ob(ObId(o)).name));
        }
    }
    // Value variables the query ranges over (a variable a filter fixed is a constant).
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < shape.num_vars(AttrTypeId(t)); ++j) {
            elements.push_back(fmt::format("{}::{}",
                                           names.value(AttrTypeId(t), acset::Value::var(j)),
                                           s.attr_type(AttrTypeId(t)).name));
        }
    }
    if (elements.empty()) {
        return "@unit";
    }
    auto facts = query_facts(q, names);
    return facts.empty()
               ? fmt::format("{{{}}}", fmt::join(elements, ", "))
               : fmt::format("{{{} | {}}}", fmt::join(elements, ", "), fmt::join(facts, ", "));
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

std::string map_text(const std::vector<MapLine>& lines) {
    std::string out;
    for (const auto& line : lines) {
        out += fmt::format("  {} ⇒ {}\n", line.name, line.image);
    }
    return out;
}

} // namespace catplan::migrate
