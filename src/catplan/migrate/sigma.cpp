#include "catplan/migrate/sigma.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/base/union_find.hpp"

#include <fmt/format.h>
#include <limits>
#include <utility>

namespace catplan::migrate {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A presentation of a state on D being closed: part nodes and value nodes, each under a union
// find, with per root the node each hom reaches and the value node each attribute holds.
class Closure {
public:
    Closure(const schema::Schema& d, std::size_t max_parts) : d_(d), max_parts_(max_parts) {
        slot_.resize(d.num_homs() + d.num_attrs(), 0);
        for (std::uint32_t o = 0; o < d.num_obs(); ++o) {
            auto homs = d.homs_from(ObId(o));
            for (std::size_t i = 0; i < homs.size(); ++i) {
                slot_[homs[i].index()] = static_cast<std::uint32_t>(i);
            }
            auto attrs = d.attrs_from(ObId(o));
            for (std::size_t i = 0; i < attrs.size(); ++i) {
                slot_[d.num_homs() + attrs[i].index()] = static_cast<std::uint32_t>(i);
            }
        }
    }

    std::size_t num_nodes() const { return sort_.size(); }

    bool failed() const { return !error_.empty(); }

    const std::string& error() const { return error_; }

    std::uint32_t new_node(ObId ob, std::string_view name) {
        if (sort_.size() >= max_parts_) {
            if (error_.empty()) {
                error_ = fmt::format("Σ has more than {} parts: the source schema has a cycle of "
                                     "homs, so the pushforward is infinite",
                                     max_parts_);
            }
            return kNone;
        }
        auto n = parts_.make_set();
        sort_.push_back(ob);
        name_.emplace_back(name);
        succ_.emplace_back(d_.homs_from(ob).size(), kNone);
        cell_.emplace_back(d_.attrs_from(ob).size(), kNone);
        return n;
    }

    std::uint32_t new_value(AttrTypeId type, Value constant, std::string_view name = {}) {
        auto v = values_.make_set();
        value_type_.push_back(type);
        value_const_.push_back(constant);
        value_name_.emplace_back(name);
        return v;
    }

    std::uint32_t find(std::uint32_t n) { return parts_.find(n); }

    std::uint32_t find_value(std::uint32_t v) { return values_.find(v); }

    /// The node that hom h reaches from n, made when there is none.
    std::uint32_t succ(std::uint32_t n, HomId h) {
        n = find(n);
        std::uint32_t s = succ_[n][slot_[h.index()]];
        if (s == kNone) {
            s = new_node(d_.hom(h).codom, {});
            if (s != kNone) {
                succ_[n][slot_[h.index()]] = s;
            }
        }
        return s;
    }

    /// The value node attribute a holds at n, made when there is none.
    std::uint32_t cell(std::uint32_t n, AttrId a) {
        n = find(n);
        std::uint32_t& slot = cell_[n][slot_[d_.num_homs() + a.index()]];
        if (slot == kNone) {
            slot = new_value(d_.attr(a).codom, Value{});
        }
        return slot;
    }

    /// The end of a path from n (kNone after a failure).
    std::uint32_t walk(std::uint32_t n, const std::vector<HomId>& homs) {
        for (HomId h : homs) {
            if (n == kNone) {
                return kNone;
            }
            n = succ(n, h);
        }
        return n;
    }

    /// Identifies two part nodes and, by congruence, everything they reach; true when they were
    /// distinct.
    bool merge(std::uint32_t a, std::uint32_t b) {
        if (a == kNone || b == kNone || find(a) == find(b)) {
            return false;
        }
        std::vector<std::pair<std::uint32_t, std::uint32_t>> pending{{a, b}};
        while (!pending.empty()) {
            auto [x, y] = pending.back();
            pending.pop_back();
            x = find(x);
            y = find(y);
            if (x == y) {
                continue;
            }
            parts_.union_sets(x, y);
            std::uint32_t root = find(x), other = root == x ? y : x;
            if (name_[root].empty()) {
                name_[root] = name_[other];
            }
            for (std::size_t i = 0; i < succ_[other].size(); ++i) {
                std::uint32_t s = succ_[other][i];
                if (s == kNone) {
                    continue;
                }
                if (succ_[root][i] == kNone) {
                    succ_[root][i] = s;
                } else {
                    pending.emplace_back(succ_[root][i], s);
                }
            }
            for (std::size_t i = 0; i < cell_[other].size(); ++i) {
                std::uint32_t v = cell_[other][i];
                if (v == kNone) {
                    continue;
                }
                if (cell_[root][i] == kNone) {
                    cell_[root][i] = v;
                } else {
                    merge_values(cell_[root][i], v);
                }
            }
        }
        return true;
    }

    /// Identifies two value nodes; two different constants are a failure.
    bool merge_values(std::uint32_t a, std::uint32_t b) {
        a = find_value(a);
        b = find_value(b);
        if (a == b) {
            return false;
        }
        const Value& ca = value_const_[a];
        const Value& cb = value_const_[b];
        if (ca.is_concrete() && cb.is_concrete() && !(ca == cb)) {
            if (error_.empty()) {
                error_ = fmt::format("Σ identifies the constants {} and {}", ca.to_string(),
                                     cb.to_string());
            }
            return false;
        }
        values_.union_sets(a, b);
        std::uint32_t root = find_value(a), other = root == a ? b : a;
        if (!value_const_[root].is_concrete()) {
            value_const_[root] = value_const_[other];
        }
        if (value_name_[root].empty()) {
            value_name_[root] = value_name_[other];
        }
        return true;
    }

    /// Closes the presentation (a chase): in the order nodes are made, each root node gets a
    /// node for every hom of its object and D's path equations are made to hold at it. Merging
    /// keeps both (congruence closure), so a node once closed stays closed, and one pass over
    /// the growing list of nodes closes everything; a new node that an equation identifies with
    /// an old one is merged before its turn comes, which is what keeps Σ finite along cycles
    /// that equations cut (refl ⋅ src == id).
    void chase() {
        for (std::uint32_t n = 0; n < sort_.size() && !failed(); ++n) {
            if (find(n) != n) {
                continue;
            }
            for (HomId h : d_.homs_from(sort_[n])) {
                (void)succ(n, h);
            }
            for (const schema::Equation& eq : d_.equations()) {
                if (eq.lhs.dom != sort_[n] || failed()) {
                    continue;
                }
                std::uint32_t l = walk(n, eq.lhs.homs), r = walk(n, eq.rhs.homs);
                if (failed()) {
                    break;
                }
                if (eq.lhs.attr && eq.rhs.attr) {
                    merge_values(cell(l, *eq.lhs.attr), cell(r, *eq.rhs.attr));
                } else {
                    merge(l, r);
                }
            }
        }
    }

    /// The closed presentation as a state on D: root nodes in the order they were made.
    ACSet state(const SchemaPtr& d) {
        ACSet out(d);
        std::vector<Part> part_of(sort_.size(), kNoPart);
        for (std::uint32_t n = 0; n < sort_.size(); ++n) {
            if (find(n) == n) {
                part_of[n] = out.add_part(sort_[n], name_[n]);
            }
        }
        for (std::uint32_t n = 0; n < sort_.size(); ++n) {
            for (AttrId a : d_.attrs_from(sort_[n])) {
                if (find(n) == n) {
                    (void)cell(n, a); // a new variable where no equation fixed the value
                }
            }
        }
        std::vector<Value> value_of(value_const_.size());
        for (std::uint32_t n = 0; n < sort_.size(); ++n) {
            if (find(n) != n) {
                continue;
            }
            auto homs = d_.homs_from(sort_[n]);
            for (std::size_t i = 0; i < homs.size(); ++i) {
                out.set_subpart(homs[i], part_of[n], part_of[find(succ_[n][i])]);
            }
            auto attrs = d_.attrs_from(sort_[n]);
            for (std::size_t i = 0; i < attrs.size(); ++i) {
                std::uint32_t v = find_value(cell(n, attrs[i]));
                if (value_of[v].is_unset()) {
                    value_of[v] = value_const_[v].is_concrete()
                                      ? value_const_[v]
                                      : out.add_var(value_type_[v], value_name_[v]);
                }
                out.set_subpart(attrs[i], part_of[n], value_of[v]);
            }
        }
        return out;
    }

private:
    const schema::Schema& d_;
    std::size_t max_parts_;
    std::vector<std::uint32_t> slot_; // position of each hom (then attr) among its object's
    UnionFind parts_;
    std::vector<ObId> sort_;
    std::vector<std::string> name_;
    std::vector<std::vector<std::uint32_t>> succ_, cell_; // meaningful at roots
    UnionFind values_;
    std::vector<AttrTypeId> value_type_;
    std::vector<Value> value_const_;
    std::vector<std::string> value_name_;
    std::string error_;
};

} // namespace

Result<ACSet> sigma(const SchemaMap& f, const ACSet& y, std::size_t max_parts) {
    CATPLAN_ASSERT(&y.schema() == f.target().get(), "sigma: the state is not on the map's target");
    if (!f.is_delta()) {
        return fail("Σ is defined here for delta maps only (every object to an object, every "
                    "hom to a path), and this map has a conjunctive query");
    }
    const schema::Schema& t = *f.target();
    Closure c(*f.source(), max_parts);
    std::vector<std::vector<std::uint32_t>> node(t.num_obs());
    for (std::uint32_t o = 0; o < t.num_obs(); ++o) {
        for (Part p = 0; p < y.num_parts(ObId(o)); ++p) {
            node[o].push_back(c.new_node(f.plain_ob(ObId(o)), y.part_name(ObId(o), p)));
        }
    }
    if (c.failed()) {
        return fail(c.error());
    }
    // F(h)(p) == h(p) for each hom h of the target.
    for (std::uint32_t h = 0; h < t.num_homs(); ++h) {
        ObId dom = t.hom(HomId(h)).dom, codom = t.hom(HomId(h)).codom;
        const std::vector<HomId>& path = *f.hom_image(HomId(h)).path;
        for (Part p = 0; p < y.num_parts(dom); ++p) {
            Part q = y.subpart(HomId(h), p);
            if (q != kNoPart) {
                c.merge(c.walk(node[dom.index()][p], path), node[codom.index()][q]);
            }
        }
    }
    // F(a)(p) == a(p) for each attribute a of the target sent to a path; a variable of Y is one
    // value node wherever it stands. An attribute sent to a constant constrains Y, not Σ(Y).
    std::vector<std::vector<std::uint32_t>> var_node(t.num_attr_types());
    for (std::uint32_t a = 0; a < t.num_attrs(); ++a) {
        const AttrImage& im = f.attr_image(AttrId(a));
        if (im.kind != AttrImage::Kind::Path) {
            continue;
        }
        AttrTypeId ty = t.attr(AttrId(a)).codom;
        auto& vars = var_node[ty.index()];
        ObId dom = t.attr(AttrId(a)).dom;
        for (Part p = 0; p < y.num_parts(dom) && !c.failed(); ++p) {
            const Value& v = y.subpart(AttrId(a), p);
            if (v.is_unset()) {
                continue;
            }
            std::uint32_t end = c.walk(node[dom.index()][p], im.homs);
            if (c.failed()) {
                break;
            }
            std::uint32_t cell = c.cell(end, im.attr);
            if (v.is_concrete()) {
                c.merge_values(cell, c.new_value(f.source()->attr(im.attr).codom, v));
                continue;
            }
            if (vars.empty()) {
                vars.assign(y.num_vars(ty), kNone);
            }
            std::uint32_t& vn = vars[v.var_index()];
            if (vn == kNone) {
                vn = c.new_value(f.source()->attr(im.attr).codom, Value{},
                                 y.var_name(ty, v.var_index()));
            }
            c.merge_values(cell, vn);
        }
    }
    c.chase();
    if (c.failed()) {
        return fail(c.error());
    }
    return c.state(f.source());
}

} // namespace catplan::migrate
