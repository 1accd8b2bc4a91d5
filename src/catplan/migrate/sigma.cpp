#include "catplan/migrate/sigma.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/colimit/presentation.hpp"

#include <fmt/format.h>
#include <utility>

namespace catplan::migrate {
namespace {

// A problem of Σ's presentation in words.
std::string describe(const colimit::PresentationProblem& p, std::size_t max_parts) {
    if (p.kind == colimit::PresentationProblemKind::TooManyParts) {
        return fmt::format("Σ has more than {} parts: the source schema has a cycle of homs, so "
                           "the pushforward is infinite",
                           max_parts);
    }
    return fmt::format("Σ identifies the constants {} and {}", p.first.to_string(),
                       p.second.to_string());
}

} // namespace

Result<ACSet> sigma(const SchemaMap& f, const ACSet& y, std::size_t max_parts) {
    CATPLAN_ASSERT(&y.schema() == f.target().get(), "sigma: the state is not on the map's target");
    if (!f.is_delta()) {
        return fail("Σ is defined here for delta maps only (every object to an object, every "
                    "hom to a path), and this map has a conjunctive query");
    }
    const schema::Schema& t = *f.target();
    colimit::Presentation c(f.source());
    c.set_max_parts(max_parts);
    auto failure = [&] { return fail(describe(c.problems().front(), max_parts)); };
    // A generator of F(c') for each part of Y at c'.
    std::vector<std::vector<colimit::Node>> node(t.num_obs());
    for (std::uint32_t o = 0; o < t.num_obs(); ++o) {
        for (Part p = 0; p < y.num_parts(ObId(o)); ++p) {
            node[o].push_back(c.add_part(f.plain_ob(ObId(o)), y.part_name(ObId(o), p)));
        }
    }
    if (c.limit_reached()) {
        return failure();
    }
    // F(h)(p) == h(p) for each hom h of the target.
    for (std::uint32_t h = 0; h < t.num_homs(); ++h) {
        ObId dom = t.hom(HomId(h)).dom, codom = t.hom(HomId(h)).codom;
        const std::vector<HomId>& path = *f.hom_image(HomId(h)).path;
        for (Part p = 0; p < y.num_parts(dom); ++p) {
            Part q = y.subpart(HomId(h), p);
            if (q != kNoPart) {
                c.equate_parts(c.path(node[dom.index()][p], path), node[codom.index()][q]);
            }
        }
    }
    // F(a)(p) == a(p) for each attribute a of the target sent to a path; a variable of Y is one
    // value node wherever it stands. An attribute sent to a constant constrains Y, not Σ(Y).
    std::vector<std::vector<colimit::Node>> var_node(t.num_attr_types());
    for (std::uint32_t a = 0; a < t.num_attrs() && c.problems().empty(); ++a) {
        const AttrImage& im = f.attr_image(AttrId(a));
        if (im.kind != AttrImage::Kind::Path) {
            continue;
        }
        AttrTypeId ty = t.attr(AttrId(a)).codom;
        AttrTypeId source_ty = f.source()->attr(im.attr).codom;
        auto& vars = var_node[ty.index()];
        ObId dom = t.attr(AttrId(a)).dom;
        for (Part p = 0; p < y.num_parts(dom) && c.problems().empty(); ++p) {
            const Value& v = y.subpart(AttrId(a), p);
            if (v.is_unset()) {
                continue;
            }
            colimit::Node end = c.path(node[dom.index()][p], im.homs);
            if (end == colimit::kNoNode) {
                break;
            }
            colimit::Node cell = c.attr(end, im.attr);
            if (v.is_concrete()) {
                c.set_literal(cell, v);
                continue;
            }
            if (vars.empty()) {
                vars.assign(y.num_vars(ty), colimit::kNoNode);
            }
            colimit::Node& vn = vars[v.var_index()];
            if (vn == colimit::kNoNode) {
                vn = c.add_value(source_ty, y.var_name(ty, v.var_index()));
            }
            c.equate_values(cell, vn);
        }
    }
    if (c.problems().empty()) {
        c.complete(/*equations=*/true);
    }
    if (!c.problems().empty()) {
        return failure();
    }
    return c.build(colimit::Presentation::VariableOrder::Cells).state;
}

} // namespace catplan::migrate
