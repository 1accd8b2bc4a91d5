#include "catplan/migrate/schema_map.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/migrate/detail/loc.hpp"

#include <fmt/format.h>
#include <utility>

namespace catplan::migrate {

namespace {

std::string ob_name(const schema::Schema& s, ObId x) {
    return "'" + s.ob(x).name + "'";
}

// Why the image p of a target hom (`what`, from target object c) is not a path from where c
// goes: it starts elsewhere (the paper's Gripper => Block), or it breaks in the middle.
std::string ill_formed_image(const schema::Schema& target, const schema::Schema& source,
                             const std::string& what, ObId c, const schema::Path& p) {
    std::string image = source.path_to_string(p);
    if (!p.homs.empty() && source.hom(p.homs[0]).dom != p.dom) {
        return what + " is sent to " + image + ", which starts at " +
               ob_name(source, source.hom(p.homs[0]).dom) + ", not at " + ob_name(source, p.dom) +
               " (where " + ob_name(target, c) + " goes)";
    }
    return what + " is sent to " + image + ", which does not compose from " +
           ob_name(source, p.dom);
}

// The one query morphism the bindings determine, into image; otherwise why not.
void determine_morphism(const ACSet& from, const ACSet& to, hom::HomSearchOptions opt, Generator g,
                        SourceRange range, const std::string& what, HomImage& image,
                        std::vector<MapProblem>& out) {
    opt.max_results = 2;
    auto r = hom::find_homomorphisms(from, to, opt);
    if (!r.error.empty()) {
        out.push_back({Severity::Error, MapProblemKind::NotUnique, g, range,
                       what + ": the query morphism is not determined: " + r.error});
    } else if (r.count == 0) {
        out.push_back({Severity::Error, MapProblemKind::WrongEnds, g, range,
                       what + ": its image is not a morphism of queries (an equation or literal "
                              "of the codomain's query does not hold in the domain's)"});
    } else if (r.count > 1) {
        out.push_back({Severity::Error, MapProblemKind::NotUnique, g, range,
                       what + ": its image determines more than one query morphism"});
    } else {
        image.morphism = std::move(r.morphisms[0]);
    }
}

} // namespace

SchemaMap::SchemaMap(SchemaPtr target, SchemaPtr source)
    : target_(std::move(target)),
      source_(std::move(source)),
      obs_(target_->num_obs()),
      homs_(target_->num_homs()),
      attr_types_(target_->num_attr_types()),
      attrs_(target_->num_attrs()) {}

namespace {

template <class Entry>
void note_twice(Entry& e, std::vector<MapProblem>& out, Generator g, SourceRange range,
                const std::string& name) {
    if (e.set) {
        out.push_back({Severity::Error, MapProblemKind::MappedTwice, g, range,
                       "'" + name + "' is mapped twice"});
    }
    e.set = true;
    e.range = range;
}

} // namespace

void SchemaMap::map_ob(ObId target, Query query, SourceRange range) {
    finished_ = false;
    auto& e = obs_[target.index()];
    note_twice(e, build_problems_, {GeneratorKind::Ob, target.index()}, range,
               target_->ob(target).name);
    e.query.emplace(std::move(query));
}

void SchemaMap::map_ob(ObId target, ObId source, SourceRange range) {
    map_ob(target, Query::representable(source_, source, target_->ob(target).name), range);
}

void SchemaMap::map_hom(HomId target, std::vector<Term> node_images, SourceRange range) {
    finished_ = false;
    auto& e = homs_[target.index()];
    note_twice(e, build_problems_, {GeneratorKind::Hom, target.index()}, range,
               target_->hom(target).name);
    e.terms = std::move(node_images);
    e.path.reset();
}

void SchemaMap::map_hom_path(HomId target, std::vector<HomId> path, SourceRange range) {
    finished_ = false;
    auto& e = homs_[target.index()];
    note_twice(e, build_problems_, {GeneratorKind::Hom, target.index()}, range,
               target_->hom(target).name);
    e.path = std::move(path);
    e.terms.reset();
}

void SchemaMap::map_attr_type(AttrTypeId target, AttrTypeId source, SourceRange range) {
    finished_ = false;
    auto& e = attr_types_[target.index()];
    note_twice(e, build_problems_, {GeneratorKind::AttrType, target.index()}, range,
               target_->attr_type(target).name);
    e.type = source;
    e.kind = source_->attr_type(source).kind;
}

void SchemaMap::map_attr_type(AttrTypeId target, ValueKind kind, SourceRange range) {
    finished_ = false;
    auto& e = attr_types_[target.index()];
    note_twice(e, build_problems_, {GeneratorKind::AttrType, target.index()}, range,
               target_->attr_type(target).name);
    e.type.reset();
    e.kind = kind;
}

void SchemaMap::map_attr(AttrId target, Term term, SourceRange range) {
    finished_ = false;
    auto& e = attrs_[target.index()];
    note_twice(e, build_problems_, {GeneratorKind::Attr, target.index()}, range,
               target_->attr(target).name);
    if (term.is_literal()) {
        e.constant = term.literal;
        e.term.reset();
    } else {
        e.term = std::move(term);
        e.constant.reset();
    }
}

void SchemaMap::map_attr_constant(AttrId target, Value value, SourceRange range) {
    finished_ = false;
    auto& e = attrs_[target.index()];
    note_twice(e, build_problems_, {GeneratorKind::Attr, target.index()}, range,
               target_->attr(target).name);
    e.constant = value;
    e.term.reset();
}

ValueKind SchemaMap::attr_type_kind(AttrTypeId target) const {
    const auto& e = attr_types_[target.index()];
    return e.type ? source_->attr_type(*e.type).kind : e.kind;
}

bool SchemaMap::is_delta() const {
    for (const auto& o : obs_) {
        if (!o.query || !o.query->is_plain()) {
            return false;
        }
    }
    for (const auto& h : homs_) {
        if (!h.image.path) {
            return false;
        }
    }
    for (const auto& a : attrs_) {
        if (a.image.kind == AttrImage::Kind::Value) {
            return false;
        }
    }
    return true;
}

// A hom sent to a path: its image between plain queries (true: done, or reported), else the
// path as the one term of the codomain's query (false: compile the terms).
bool SchemaMap::compile_hom_path(HomId f, std::vector<MapProblem>& out) {
    const schema::Schema& t = *target_;
    auto& e = homs_[f.index()];
    Generator g{GeneratorKind::Hom, f.index()};
    ObId c = t.hom(f).dom, d = t.hom(f).codom;
    const Query& qc = *obs_[c.index()].query;
    const Query& qd = *obs_[d.index()].query;
    std::string what = "'" + t.hom(f).name + "'";
    if (qc.nodes().empty() || qc.nodes()[0].is_value) {
        out.push_back({Severity::Error, MapProblemKind::WrongEnds, g, e.range,
                       what + " is sent to a path, but its domain's query has no object "
                              "variable to start from"});
        return true;
    }
    schema::Path p{qc.nodes()[0].ob, *e.path, std::nullopt};
    if (!source_->is_well_formed(p)) {
        out.push_back({Severity::Error, MapProblemKind::WrongEnds, g, e.range,
                       ill_formed_image(t, *source_, what, c, p)});
        return true;
    }
    if (qc.is_plain() && qd.is_plain()) {
        ObId end = source_->path_codom_ob(p);
        if (end != qd.nodes()[0].ob) {
            out.push_back({Severity::Error, MapProblemKind::WrongEnds, g, e.range,
                           what + " is sent to " + source_->path_to_string(p) + ", which ends at " +
                               ob_name(*source_, end) + ", not at " +
                               ob_name(*source_, qd.nodes()[0].ob)});
            return true;
        }
        if (e.path->empty()) {
            out.push_back({Severity::Warning, MapProblemKind::IdentityImage, g, e.range,
                           what + " is sent to an identity"});
        }
        e.image.path = *e.path;
        return true;
    }
    e.terms = std::vector<Term>{Term::path(qc.nodes()[0].name, *e.path)};
    return false;
}

void SchemaMap::compile_hom(HomId f, std::vector<MapProblem>& out) {
    const schema::Schema& t = *target_;
    auto& e = homs_[f.index()];
    e.image = {};
    Generator g{GeneratorKind::Hom, f.index()};
    ObId c = t.hom(f).dom, d = t.hom(f).codom;
    if (!obs_[c.index()].query || !obs_[d.index()].query) {
        return; // the unmapped object is reported already
    }
    Query& qc = *obs_[c.index()].query;
    const Query& qd = *obs_[d.index()].query;
    if (qc.is_empty()) {
        e.image.morphism = ACSetMorphism{}; // no elements: nothing to send anywhere
        return;
    }
    std::string what = "'" + t.hom(f).name + "'";
    if (e.path && compile_hom_path(f, out)) {
        return;
    }
    if (!e.terms) {
        return;
    }
    const std::vector<Term>& terms = *e.terms;
    // Plain to plain with one bare path: a delta entry.
    if (qc.is_plain() && qd.is_plain() && terms.size() == 1 && !terms[0].is_literal() &&
        terms[0].var == qc.nodes()[0].name && !terms[0].attr) {
        schema::Path p{qc.nodes()[0].ob, terms[0].homs, std::nullopt};
        if (source_->is_well_formed(p) && source_->path_codom_ob(p) == qd.nodes()[0].ob) {
            if (p.homs.empty()) {
                out.push_back({Severity::Warning, MapProblemKind::IdentityImage, g, e.range,
                               what + " is sent to an identity"});
            }
            e.image.path = p.homs;
            return;
        }
    }
    if (terms.size() != qd.nodes().size()) {
        out.push_back({Severity::Error, MapProblemKind::WrongEnds, g, e.range,
                       what + " gives " + std::to_string(terms.size()) +
                           " images, but its codomain's query has " +
                           std::to_string(qd.nodes().size()) + " variables"});
        return;
    }
    hom::HomSearchOptions opt;
    bool bad = false;
    const ACSet& qd_state = qd.state();
    for (std::size_t i = 0; i < terms.size(); ++i) {
        const QueryNode& n = qd.nodes()[i];
        QueryElement target_el = qd.locate_node(i);
        QueryElement el;
        if (terms[i].is_literal()) {
            el.is_value = true;
            el.value = terms[i].literal;
            el.type = n.type;
            if (!n.is_value) {
                out.push_back({Severity::Error, MapProblemKind::WrongEnds, g,
                               terms[i].range.valid() ? terms[i].range : e.range,
                               what + ": variable '" + n.name +
                                   "' is over an object but is sent to a literal"});
                bad = true;
                continue;
            }
        } else {
            // Terms were added to qc in finish()'s first pass; adding again finds the same class.
            std::size_t before = qc.problems().size();
            auto h = qc.add_term(terms[i]);
            if (!h) {
                for (std::size_t k = before; k < qc.problems().size(); ++k) {
                    out.push_back(
                        {Severity::Error, MapProblemKind::BadQuery, g,
                         qc.problems()[k].range.valid() ? qc.problems()[k].range : e.range,
                         what + ": " + qc.problems()[k].message});
                }
                bad = true;
                continue;
            }
            el = qc.locate(*h);
        }
        bool same = el.is_value == n.is_value && (n.is_value ? el.type == n.type : el.ob == n.ob);
        if (n.is_value && el.is_value && terms[i].is_literal()) {
            same = true;
        }
        if (!same) {
            std::string want =
                n.is_value ? "'" + source_->attr_type(n.type).name + "'" : ob_name(*source_, n.ob);
            out.push_back({Severity::Error, MapProblemKind::WrongEnds, g,
                           terms[i].range.valid() ? terms[i].range : e.range,
                           fmt::format("{}: variable '{}' of {} is sent to a term of another type",
                                       what, n.name, want)});
            bad = true;
            continue;
        }
        if (!n.is_value) {
            opt.bind(n.ob, target_el.part, el.part);
        } else if (target_el.value.is_var()) {
            opt.bind_var(n.type, target_el.value.var_index(), el.value);
        } else if (!(target_el.value == el.value)) {
            out.push_back({Severity::Error, MapProblemKind::WrongEnds, g, e.range,
                           what + ": variable '" + n.name + "' is fixed to " +
                               target_el.value.to_string() + " but is sent to " +
                               el.value.to_string()});
            bad = true;
        }
    }
    if (bad) {
        return;
    }
    determine_morphism(qd_state, qc.state(), std::move(opt), g, e.range, what, e.image, out);
}

void SchemaMap::compile_attr(AttrId a, std::vector<MapProblem>& out) {
    const schema::Schema& t = *target_;
    auto& e = attrs_[a.index()];
    e.image = {};
    Generator g{GeneratorKind::Attr, a.index()};
    ObId c = t.attr(a).dom;
    AttrTypeId tt = t.attr(a).codom;
    if (!obs_[c.index()].query || !attr_types_[tt.index()].set) {
        return;
    }
    const Query& qc = *obs_[c.index()].query;
    if (qc.is_empty()) {
        return;
    }
    std::string what = "'" + t.attr(a).name + "'";
    const auto& te = attr_types_[tt.index()];
    ValueKind kind = attr_type_kind(tt);
    if (e.constant) {
        if (kind != ValueKind::Unknown && e.constant->kind() != kind) {
            out.push_back({Severity::Error, MapProblemKind::WrongValueKind, g, e.range,
                           what + " is sent to " + e.constant->to_string() + ", which is not a " +
                               std::string(schema::to_string(kind))});
            return;
        }
        e.image.kind = AttrImage::Kind::Constant;
        e.image.constant = *e.constant;
        return;
    }
    if (!e.term) {
        return;
    }
    if (!te.type) {
        out.push_back({Severity::Error, MapProblemKind::NotConstant, g, e.range,
                       what + " goes into '" + t.attr_type(tt).name + "', which is mapped to " +
                           std::string(schema::to_string(kind)) + " alone: it must be a constant"});
        return;
    }
    const Term& term = *e.term;
    auto node = qc.find_node(term.var);
    SourceRange at = term.range.valid() ? term.range : e.range;
    if (!node) {
        out.push_back({Severity::Error, MapProblemKind::BadQuery, g, at,
                       what + ": unknown variable '" + term.var + "'"});
        return;
    }
    const QueryNode& n = qc.nodes()[*node];
    if (n.is_value) {
        if (!term.homs.empty() || term.attr) {
            out.push_back({Severity::Error, MapProblemKind::BadQuery, g, at,
                           what + ": '" + n.name + "' is a value"});
            return;
        }
        if (n.type != *te.type) {
            out.push_back({Severity::Error, MapProblemKind::WrongValueKind, g, at,
                           what + " is sent to '" + n.name + "' of type '" +
                               source_->attr_type(n.type).name + "', not '" +
                               source_->attr_type(*te.type).name + "'"});
            return;
        }
        QueryElement el = qc.locate_node(*node);
        e.image.kind = AttrImage::Kind::Value;
        e.image.type = n.type;
        e.image.value = el.value;
        return;
    }
    schema::Path p{n.ob, term.homs, term.attr};
    if (!source_->is_well_formed(p) || !term.attr) {
        out.push_back({Severity::Error, MapProblemKind::WrongValueKind, g, at,
                       what + " is sent to " + source_->path_to_string(p) + ", which " +
                           (term.attr ? "does not compose" : "does not end in an attribute")});
        return;
    }
    if (source_->attr(*term.attr).codom != *te.type) {
        out.push_back({Severity::Error, MapProblemKind::WrongValueKind, g, at,
                       what + " is sent to '" + source_->attr(*term.attr).name + "' into '" +
                           source_->attr_type(source_->attr(*term.attr).codom).name + "', not '" +
                           source_->attr_type(*te.type).name + "'"});
        return;
    }
    e.image.kind = AttrImage::Kind::Path;
    e.image.start_ob = n.ob;
    e.image.start = qc.locate_node(*node).part;
    e.image.homs = term.homs;
    e.image.attr = *term.attr;
}

namespace {

using detail::Loc;

// A Loc moved along its suffix as far as the query's shape has the homs.
Loc canonical(const schema::Schema& s, const Query& q, Loc loc) {
    const ACSet& st = q.state();
    while (!loc.suffix.empty() && st.subpart(loc.suffix.front(), loc.part) != kNoPart) {
        loc.part = st.subpart(loc.suffix.front(), loc.part);
        loc.ob = s.hom(loc.suffix.front()).codom;
        loc.suffix.erase(loc.suffix.begin());
    }
    return loc;
}

bool same_loc(const schema::Schema& s, const Loc& a, const Loc& b) {
    return a.ob == b.ob && a.part == b.part && a.attr == b.attr &&
           s.paths_equal({a.ob, a.suffix, a.attr}, {b.ob, b.suffix, b.attr});
}

// The images of one side of an equation: a Loc per object node of the end's query, or an
// attribute's constant.
struct Side {
    bool usable = true;
    std::vector<Loc> locs;
    std::optional<Value> constant;
};

bool same_side(const schema::Schema& s, const Side& a, const Side& b) {
    if (a.constant.has_value() != b.constant.has_value()) {
        return false;
    }
    if (a.constant) {
        return *a.constant == *b.constant;
    }
    if (a.locs.size() != b.locs.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.locs.size(); ++i) {
        if (!same_loc(s, a.locs[i], b.locs[i])) {
            return false;
        }
    }
    return true;
}

} // namespace

Loc detail::step_back(const SchemaMap& m, HomId f, Loc loc) {
    const HomImage& im = m.hom_image(f);
    const Query& qc = m.query(m.target()->hom(f).dom);
    if (im.path) {
        Loc r = loc;
        r.ob = qc.nodes()[0].ob;
        r.part = qc.locate_node(0).part;
        r.suffix = *im.path;
        r.suffix.insert(r.suffix.end(), loc.suffix.begin(), loc.suffix.end());
        return r;
    }
    loc.part = (*im.morphism)(loc.ob, loc.part);
    return loc;
}

void SchemaMap::check_equations(std::vector<MapProblem>& out) {
    const schema::Schema& t = *target_;
    const schema::Schema& s = *source_;
    // The image in Q_dom of a Loc of Q_codom, along target hom f : dom -> codom.
    auto side = [&](const schema::Path& p) {
        Side out_side;
        for (HomId h : p.homs) {
            const HomImage& im = homs_[h.index()].image;
            if (!im.path && !im.morphism) {
                out_side.usable = false;
                return out_side;
            }
        }
        ObId end = p.homs.empty() ? p.dom : t.hom(p.homs.back()).codom;
        const Query& qe = *obs_[end.index()].query;
        if (qe.is_empty()) {
            out_side.usable = false;
            return out_side;
        }
        std::vector<Loc> locs;
        if (p.attr) {
            const AttrImage& ai = attrs_[p.attr->index()].image;
            if (ai.kind == AttrImage::Kind::Constant) {
                out_side.constant = ai.constant;
                return out_side;
            }
            if (ai.kind != AttrImage::Kind::Path) {
                out_side.usable = false; // value variables are not compared
                return out_side;
            }
            locs.push_back({ai.start_ob, ai.start, ai.homs, ai.attr});
        } else {
            for (std::size_t i = 0; i < qe.nodes().size(); ++i) {
                if (!qe.nodes()[i].is_value) {
                    locs.push_back({qe.nodes()[i].ob, qe.locate_node(i).part, {}, std::nullopt});
                }
            }
        }
        for (auto it = p.homs.rbegin(); it != p.homs.rend(); ++it) {
            if (obs_[t.hom(*it).dom.index()].query->is_empty()) {
                out_side.usable = false;
                return out_side;
            }
            for (Loc& l : locs) {
                l = detail::step_back(*this, *it, l);
            }
        }
        const Query& qc = *obs_[p.dom.index()].query;
        for (Loc& l : locs) {
            out_side.locs.push_back(canonical(s, qc, l));
        }
        return out_side;
    };
    for (std::size_t k = 0; k < t.equations().size(); ++k) {
        const schema::Equation& eq = t.equations()[k];
        if (!obs_[eq.lhs.dom.index()].query || obs_[eq.lhs.dom.index()].query->is_empty()) {
            continue;
        }
        bool mapped = true;
        for (const schema::Path* p : {&eq.lhs, &eq.rhs}) {
            for (HomId h : p->homs) {
                mapped = mapped && obs_[t.hom(h).codom.index()].query.has_value();
            }
            if (p->attr) {
                mapped = mapped && attrs_[p->attr->index()].image.kind != AttrImage::Kind::None;
            }
        }
        if (!mapped) {
            continue;
        }
        Side a = side(eq.lhs), b = side(eq.rhs);
        if (!a.usable || !b.usable) {
            continue;
        }
        if (!same_side(s, a, b)) {
            Generator g = !eq.lhs.homs.empty()
                              ? Generator{GeneratorKind::Hom, eq.lhs.homs[0].index()}
                              : Generator{GeneratorKind::Attr, eq.lhs.attr->index()};
            SourceRange range = eq.range.valid()               ? eq.range
                                : g.kind == GeneratorKind::Hom ? homs_[g.index].range
                                                               : attrs_[g.index].range;
            out.push_back({Severity::Error, MapProblemKind::EquationNotPreserved, g, range,
                           "the equation " + t.path_to_string(eq.lhs) +
                               " == " + t.path_to_string(eq.rhs) + " is not preserved by the map"});
        }
    }
}

// The attribute types, homs and attributes that are not mapped; a hom into the unit query is
// mapped by the only morphism there is.
void SchemaMap::unmapped_problems(std::vector<MapProblem>& out) {
    const schema::Schema& t = *target_;
    for (std::uint32_t i = 0; i < t.num_attr_types(); ++i) {
        if (!attr_types_[i].set) {
            out.push_back(
                {Severity::Error,
                 MapProblemKind::Unmapped,
                 {GeneratorKind::AttrType, i},
                 {},
                 "attribute type '" + t.attr_type(AttrTypeId(i)).name + "' is not mapped"});
        }
    }
    auto dom_empty = [&](ObId c) {
        return obs_[c.index()].query && obs_[c.index()].query->is_empty();
    };
    // A hom into the unit query (@unit, no variables) has exactly one image, the query morphism
    // that sends nothing anywhere: it need not be written (as in DataMigrations).
    auto is_unit = [&](ObId c) {
        const auto& q = obs_[c.index()].query;
        return q && !q->is_empty() && q->nodes().empty();
    };
    for (std::uint32_t i = 0; i < t.num_homs(); ++i) {
        if (!homs_[i].set && is_unit(t.hom(HomId(i)).codom)) {
            homs_[i].set = true;
            homs_[i].terms = std::vector<Term>{};
            homs_[i].path.reset();
        }
    }
    for (std::uint32_t i = 0; i < t.num_homs(); ++i) {
        if (!homs_[i].set && !dom_empty(t.hom(HomId(i)).dom)) {
            out.push_back({Severity::Error,
                           MapProblemKind::Unmapped,
                           {GeneratorKind::Hom, i},
                           {},
                           "hom '" + t.hom(HomId(i)).name + "' is not mapped"});
        }
    }
    for (std::uint32_t i = 0; i < t.num_attrs(); ++i) {
        if (!attrs_[i].set && !dom_empty(t.attr(AttrId(i)).dom)) {
            out.push_back({Severity::Error,
                           MapProblemKind::Unmapped,
                           {GeneratorKind::Attr, i},
                           {},
                           "attribute '" + t.attr(AttrId(i)).name + "' is not mapped"});
        }
    }
}

// A value variable that no attribute cell holds could be anything: infinitely many tuples.
void SchemaMap::free_value_problems(std::vector<MapProblem>& out) const {
    const schema::Schema& t = *target_;
    for (std::uint32_t i = 0; i < t.num_obs(); ++i) {
        const auto& e = obs_[i];
        if (!e.query || e.query->is_empty()) {
            continue;
        }
        for (std::size_t n = 0; n < e.query->nodes().size(); ++n) {
            const QueryNode& node = e.query->nodes()[n];
            if (!node.is_value) {
                continue;
            }
            QueryElement el = e.query->locate_node(n);
            if (el.value.is_var() &&
                e.query->state().var_incident(node.type, el.value.var_index()).empty()) {
                out.push_back({Severity::Error,
                               MapProblemKind::FreeValueVariable,
                               {GeneratorKind::Ob, i},
                               node.range.valid() ? node.range : e.range,
                               "value variable '" + node.name +
                                   "' is not reached by any attribute, so it could be anything"});
            }
        }
    }
}

std::vector<MapProblem> SchemaMap::finish() {
    std::vector<MapProblem> out = build_problems_;
    const schema::Schema& t = *target_;
    for (std::uint32_t i = 0; i < t.num_obs(); ++i) {
        const auto& e = obs_[i];
        Generator g{GeneratorKind::Ob, i};
        if (!e.query) {
            out.push_back({Severity::Error,
                           MapProblemKind::Unmapped,
                           g,
                           {},
                           "object '" + t.ob(ObId(i)).name + "' is not mapped"});
            continue;
        }
        for (const QueryProblem& p : e.query->problems()) {
            out.push_back({Severity::Error, MapProblemKind::BadQuery, g,
                           p.range.valid() ? p.range : e.range, p.message});
        }
    }
    unmapped_problems(out);
    // First pass: mention every hom image's terms, so that each query has its final shape before
    // any query morphism into or out of it is computed.
    for (std::uint32_t i = 0; i < t.num_homs(); ++i) {
        auto& e = homs_[i];
        ObId c = t.hom(HomId(i)).dom;
        if (!e.terms || !obs_[c.index()].query || obs_[c.index()].query->is_empty()) {
            continue;
        }
        Query& qc = *obs_[c.index()].query;
        for (const Term& term : *e.terms) {
            if (!term.is_literal() && qc.find_node(term.var)) {
                (void)qc.add_term(term); // problems are reported by compile_hom
            }
        }
    }
    for (std::uint32_t i = 0; i < t.num_homs(); ++i) {
        if (homs_[i].set) {
            compile_hom(HomId(i), out);
        }
    }
    for (std::uint32_t i = 0; i < t.num_attrs(); ++i) {
        if (attrs_[i].set) {
            compile_attr(AttrId(i), out);
        }
    }
    free_value_problems(out);
    bool errors = false;
    for (const MapProblem& p : out) {
        errors = errors || p.severity == Severity::Error;
    }
    if (!errors) {
        check_equations(out);
        for (const MapProblem& p : out) {
            errors = errors || p.severity == Severity::Error;
        }
    }
    finished_ = true;
    ok_ = !errors;
    return out;
}

} // namespace catplan::migrate
