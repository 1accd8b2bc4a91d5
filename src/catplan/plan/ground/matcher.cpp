#include "catplan/plan/ground/matcher.hpp"

#include <algorithm>
#include <deque>
#include <optional>

namespace catplan::plan::ground {

namespace {

// How the search reaches a part: from an earlier part along a hom (forward: earlier.f == this;
// backward: this.f == earlier), or by trying every candidate.
struct Anchor {
    enum class Kind : std::uint8_t { Fixed, Forward, Backward, Free };
    Kind kind = Kind::Free;
    ObId ob;
    Part part = 0;
    ObId from_ob;
    Part from = 0;
    HomId hom;
    // A loose part's partner: a part of another object with its name, whose image's name the
    // loose part's image takes where it can, so that a parameter reads as one thing.
    std::optional<std::pair<ObId, Part>> partner;
};

class Matcher {
public:
    Matcher(const Universe& u, const Pattern& pat, const std::function<bool(const Match&)>& visit)
        : u_(u), s_(u.s), pat_(pat), p_(*pat.p), visit_(visit) {
        m_.images.resize(s_.num_obs());
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            m_.images[o].assign(p_.num_parts(ObId(o)), Image{});
        }
        m_.bindings.resize(s_.num_attr_types());
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            m_.bindings[t].assign(p_.num_vars(AttrTypeId(t)), Value());
            if (t < pat.bound.size()) {
                for (std::uint32_t v = 0; v < pat.bound[t].size(); ++v) {
                    m_.bindings[t][v] = pat.bound[t][v];
                }
            }
        }
        plan_order();
    }

    void run() { (void)step(0); }

private:
    bool is_fixed(ObId ob, Part p) const {
        return ob.index() < pat_.fixed.size() && pat_.fixed[ob.index()][p].id != kNone;
    }

    bool is_loose(ObId ob, Part p) const {
        return ob.index() < pat_.loose.size() && pat_.loose[ob.index()][p] != 0;
    }

    int rank(ObId ob) const {
        switch (u_.kind[ob.index()]) {
        case ObKind::Atoms:
            return 0;
        case ObKind::Slots:
            return 1;
        case ObKind::Entities:
            return 2;
        }
        return 3;
    }

    // A breadth-first order over the pattern's parts along homs (both ways), fixed parts first,
    // then each component from a part of the object most likely to have few candidates, loose
    // parts last (so that the first admissible image of one is as good as any). The parts an
    // atom points to come right after it: an atom's hom values are fixed, so they add no branch,
    // and what they check (a name) prunes the atom before its siblings branch. Queued behind
    // them, a goal's (at ball_i roomb) atoms, all reached backwards from roomb, would be tried in
    // every order before any ball's name was read: n! partial matches for n balls.
    void plan_order() {
        std::vector<std::vector<char>> seen(s_.num_obs());
        std::deque<std::pair<ObId, Part>> queue;
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            seen[o].assign(p_.num_parts(ObId(o)), 0);
        }
        auto visit = [&](Anchor a) {
            if (seen[a.ob.index()][a.part]) {
                return;
            }
            seen[a.ob.index()][a.part] = 1;
            order_.push_back(a);
            queue.emplace_back(a.ob, a.part);
            if (u_.kind[a.ob.index()] != ObKind::Atoms) {
                return;
            }
            for (HomId f : s_.homs_from(a.ob)) {
                Part t = p_.subpart(f, a.part);
                ObId cod = s_.hom(f).codom;
                if (t != kNoPart && !seen[cod.index()][t]) {
                    seen[cod.index()][t] = 1;
                    order_.push_back(
                        {Anchor::Kind::Forward, cod, t, a.ob, a.part, f, std::nullopt});
                    queue.emplace_back(cod, t);
                }
            }
        };
        auto drain = [&] {
            while (!queue.empty()) {
                auto [ob, p] = queue.front();
                queue.pop_front();
                for (HomId f : s_.homs_from(ob)) {
                    Part t = p_.subpart(f, p);
                    if (t != kNoPart) {
                        visit({Anchor::Kind::Forward, s_.hom(f).codom, t, ob, p, f, std::nullopt});
                    }
                }
                for (HomId f : s_.homs_into(ob)) {
                    for (Part q : p_.incident(f, p)) {
                        visit({Anchor::Kind::Backward, s_.hom(f).dom, q, ob, p, f, std::nullopt});
                    }
                }
            }
        };
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            for (Part p = 0; p < p_.num_parts(ObId(o)); ++p) {
                if (is_fixed(ObId(o), p)) {
                    visit({Anchor::Kind::Fixed, ObId(o), p, ObId(o), p, HomId(0), std::nullopt});
                }
            }
        }
        drain();
        for (int r = 0; r <= 3; ++r) {
            for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
                ObId ob(o);
                if (rank(ob) != r) {
                    continue;
                }
                for (Part p = 0; p < p_.num_parts(ob); ++p) {
                    if (!is_loose(ob, p)) {
                        visit({Anchor::Kind::Free, ob, p, ob, p, HomId(0), std::nullopt});
                        drain();
                    }
                }
            }
        }
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            for (Part p = 0; p < p_.num_parts(ObId(o)); ++p) {
                visit({Anchor::Kind::Free, ObId(o), p, ObId(o), p, HomId(0), partner(ObId(o), p)});
            }
        }
    }

    std::optional<std::pair<ObId, Part>> partner(ObId ob, Part p) const {
        std::string_view name = p_.part_name(ob, p);
        if (!is_loose(ob, p) || name.empty()) {
            return std::nullopt;
        }
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            for (Part q = 0; o != ob.index() && q < p_.num_parts(ObId(o)); ++q) {
                if (!is_loose(ObId(o), q) && p_.part_name(ObId(o), q) == name) {
                    return std::pair{ObId(o), q};
                }
            }
        }
        return std::nullopt;
    }

    // ---- facts ---------------------------------------------------------------------------------

    // Adds var = value unless it contradicts a fact already there.
    bool need(VarId var, std::uint32_t value) {
        for (const Fact& f : m_.facts) {
            if (f.var == var) {
                return f.value == value;
            }
        }
        m_.facts.push_back({var, value});
        return true;
    }

    std::uint32_t pos(HomId f) const { return u_.position[f.index()]; }

    std::uint32_t pos(AttrId a) const { return u_.position[s_.num_homs() + a.index()]; }

    // The hom value of an image is `target`.
    bool hom_is(Image c, HomId f, ObjectId target) {
        if (c.atom) {
            return u_.task.atoms[c.id].homs[pos(f)] == target;
        }
        const Cell& cell = u_.task.homs[c.id][pos(f)];
        if (cell.var == kNone) {
            return cell.target == target;
        }
        auto i = u_.find_hom_value(cell.var, target);
        return i != kNone && need(cell.var, i);
    }

    bool attr_is(Image c, AttrId a, const Value& v) {
        if (c.atom) {
            return u_.task.atoms[c.id].attrs[pos(a)] == v;
        }
        const Cell& cell = u_.task.attrs[c.id][pos(a)];
        if (cell.var == kNone) {
            return cell.value == v;
        }
        auto i = u_.find_attr_value(cell.var, v);
        return i != kNone && need(cell.var, i);
    }

    // ---- the search ---------------------------------------------------------------------------

    bool step(std::size_t i) {
        u_.budget.poll();
        if (i == order_.size()) {
            return visit_(m_);
        }
        const Anchor& a = order_[i];
        switch (a.kind) {
        case Anchor::Kind::Fixed:
            return attempt(i, pat_.fixed[a.ob.index()][a.part]);
        case Anchor::Kind::Forward:
            return forward(i, a);
        case Anchor::Kind::Backward: {
            Image from = m_.images[a.from_ob.index()][a.from];
            if (from.atom) {
                return true; // nothing points into an atom
            }
            Images cands = u_.pointing(a.hom, from.id); // copied: the universe does not change
            for (Image c : cands) {
                if (!attempt(i, c)) {
                    return false;
                }
            }
            return true;
        }
        case Anchor::Kind::Free:
            if (is_loose(a.ob, a.part)) {
                return loose(i, a);
            }
            for (Image c : u_.candidates(a.ob)) {
                if (!attempt(i, c)) {
                    return false;
                }
            }
            return true;
        }
        return true;
    }

    // A loose part: the first free entity gives the same transition as every other, and one
    // with fewer conditions than any slot; slots only when no entity is free.
    bool loose(std::size_t i, const Anchor& a) {
        Images cands = u_.candidates(a.ob);
        if (a.partner) {
            Image twin = m_.images[a.partner->first.index()][a.partner->second];
            auto name = [&](Image c) {
                const Object& obj = u_.task.objects[c.id];
                return c.atom || c.id == kNone || obj.is_slot()
                           ? std::string_view()
                           : u_.task.problem->initial->part_name(obj.ob, obj.initial);
            };
            auto named_as_twin = [&](Image c) {
                return !name(twin).empty() && name(c) == name(twin);
            };
            std::stable_partition(cands.begin(), cands.end(), named_as_twin);
        }
        for (Image c : cands) {
            if (!u_.task.objects[c.id].is_slot() && admissible(a.ob, a.part, c)) {
                return attempt(i, c);
            }
        }
        for (Image c : cands) {
            if (u_.task.objects[c.id].is_slot() && !attempt(i, c)) {
                return false;
            }
        }
        return true;
    }

    bool forward(std::size_t i, const Anchor& a) {
        Image from = m_.images[a.from_ob.index()][a.from];
        if (from.atom) {
            ObjectId t = u_.task.atoms[from.id].homs[pos(a.hom)];
            return t == kNone || attempt(i, {false, t});
        }
        const Cell& cell = u_.task.homs[from.id][pos(a.hom)];
        if (cell.var == kNone) {
            return cell.target == kNone || attempt(i, {false, cell.target});
        }
        const auto& targets = u_.task.vars[cell.var].targets;
        for (std::uint32_t v = 0; v < targets.size(); ++v) {
            if (targets[v] == kNone) {
                continue;
            }
            std::size_t mark = m_.facts.size();
            if (need(cell.var, v) && !attempt(i, {false, targets[v]})) {
                return false;
            }
            m_.facts.resize(mark);
        }
        return true;
    }

    // Whether c may be the image of pattern part (ob, p): its kind, monicity, presence, and the
    // homs between it and the parts placed so far.
    bool admissible(ObId ob, Part p, Image c) {
        bool atoms = u_.kind[ob.index()] == ObKind::Atoms;
        if (c.atom != atoms) {
            return false;
        }
        if (!c.atom) {
            const Object& obj = u_.task.objects[c.id];
            if (obj.ob != ob) {
                return false;
            }
            bool deleted = ob.index() < pat_.deleted.size() && pat_.deleted[ob.index()][p];
            if (deleted && !obj.is_slot()) {
                return false; // entities are never deleted
            }
            if (obj.is_slot() && (!u_.reached(obj.presence, 1) || !need(obj.presence, 1))) {
                return false;
            }
        } else {
            const Atom& at = u_.task.atoms[c.id];
            if (at.ob != ob || !u_.reached(at.var, 1) || !need(at.var, 1)) {
                return false;
            }
        }
        for (const Image& other : m_.images[ob.index()]) {
            if (other.id == c.id && other.atom == c.atom) {
                return false; // monic
            }
        }
        for (HomId f : s_.homs_from(ob)) {
            Part t = p_.subpart(f, p);
            if (t == kNoPart) {
                continue;
            }
            ObId cod = s_.hom(f).codom;
            Image ti = cod == ob && t == p ? c : m_.images[cod.index()][t];
            if (ti.id != kNone && !hom_is(c, f, ti.id)) {
                return false;
            }
        }
        for (HomId f : s_.homs_into(ob)) {
            ObId dom = s_.hom(f).dom;
            for (Part q : p_.incident(f, p)) {
                Image qi = m_.images[dom.index()][q];
                if (qi.id != kNone && !hom_is(qi, f, c.id)) {
                    return false;
                }
            }
        }
        return true;
    }

    bool attempt(std::size_t i, Image c) {
        const Anchor& a = order_[i];
        std::size_t mark = m_.facts.size();
        bool go_on = true;
        if (admissible(a.ob, a.part, c)) {
            m_.images[a.ob.index()][a.part] = c;
            go_on = attributes(i, c, 0);
            m_.images[a.ob.index()][a.part] = Image{};
        }
        m_.facts.resize(mark);
        return go_on;
    }

    // The attribute values of part order_[i] at image c, one attribute at a time (a variable of
    // the pattern read from a variable cell branches over the cell's values).
    bool attributes(std::size_t i, Image c, std::size_t k) {
        const Anchor& a = order_[i];
        auto attrs = s_.attrs_from(a.ob);
        if (k == attrs.size()) {
            return step(i + 1);
        }
        AttrId at = attrs[k];
        const Value& pv = p_.subpart(at, a.part);
        if (pv.is_unset()) {
            return attributes(i, c, k + 1);
        }
        if (pv.is_concrete()) {
            std::size_t mark = m_.facts.size();
            bool go_on = !attr_is(c, at, pv) || attributes(i, c, k + 1);
            m_.facts.resize(mark);
            return go_on;
        }
        std::uint32_t ty = s_.attr(at).codom.index();
        Value& b = m_.bindings[ty][pv.var_index()];
        bool unread = b == kAny || (ty < pat_.unread.size() && pat_.unread[ty][pv.var_index()]);
        if (unread) {
            return any_value(i, c, at, k, b);
        }
        auto try_value = [&](const Value& v, std::optional<Fact> fact) {
            if (v.is_unset() || (!b.is_unset() && (!(b == v) || v == kUnknown))) {
                return true; // no value, or another (two cells never share an unknown)
            }
            std::size_t mark = m_.facts.size();
            if (fact && !need(fact->var, fact->value)) {
                return true;
            }
            bool was_free = b.is_unset();
            b = v;
            bool go_on = attributes(i, c, k + 1);
            if (was_free) {
                b = Value();
            }
            m_.facts.resize(mark);
            return go_on;
        };
        if (c.atom) {
            return try_value(u_.task.atoms[c.id].attrs[pos(at)], std::nullopt);
        }
        const Cell& cell = u_.task.attrs[c.id][pos(at)];
        if (cell.var == kNone) {
            return try_value(cell.value, std::nullopt);
        }
        const auto& values = u_.task.vars[cell.var].values;
        for (std::uint32_t v = 0; v < values.size(); ++v) {
            if (!try_value(values[v], Fact{cell.var, v})) {
                return false;
            }
        }
        return true;
    }

    // An unread variable: the cell needs a value, any value (branching only where the cell
    // may be unset).
    bool any_value(std::size_t i, Image c, AttrId at, std::size_t k, Value& b) {
        Value before = b;
        b = kAny;
        bool go_on = true;
        const Value* fixed = nullptr;
        if (c.atom) {
            fixed = &u_.task.atoms[c.id].attrs[pos(at)];
        } else if (u_.task.attrs[c.id][pos(at)].var == kNone) {
            fixed = &u_.task.attrs[c.id][pos(at)].value;
        }
        if (fixed != nullptr) {
            go_on = fixed->is_unset() || attributes(i, c, k + 1);
        } else {
            VarId var = u_.task.attrs[c.id][pos(at)].var;
            if (u_.find_attr_value(var, Value()) == kNone) {
                go_on = attributes(i, c, k + 1);
            } else {
                const auto& values = u_.task.vars[var].values;
                for (std::uint32_t v = 0; v < values.size() && go_on; ++v) {
                    if (values[v].is_unset()) {
                        continue;
                    }
                    std::size_t mark = m_.facts.size();
                    if (need(var, v)) {
                        go_on = attributes(i, c, k + 1);
                    }
                    m_.facts.resize(mark);
                }
            }
        }
        b = before;
        return go_on;
    }

    const Universe& u_;
    const schema::Schema& s_;
    const Pattern& pat_;
    const ACSet& p_;
    const std::function<bool(const Match&)>& visit_;
    std::vector<Anchor> order_;
    Match m_;
};

// Whether expression e reads variable v of type ty.
bool reads(const rewrite::AttrExpr& e, AttrTypeId ty, std::uint32_t v) {
    if (e.op == rewrite::AttrExpr::Op::Input && e.input_type == ty && e.input_var == v) {
        return true;
    }
    return std::any_of(e.args.begin(), e.args.end(),
                       [&](const rewrite::AttrExpr& a) { return reads(a, ty, v); });
}

// Whether L variable v is carried by the rule into an R cell other than its own kept cell.
bool carried(const Rule& rule, AttrTypeId ty, std::uint32_t v) {
    const auto& s = rule.L.schema();
    for (std::uint32_t k = 0; k < rule.K.num_vars(ty); ++k) {
        const Value& lv = rule.l.var(ty, k);
        const Value& rv = rule.r.var(ty, k);
        if (!lv.is_var() || lv.var_index() != v || !rv.is_var()) {
            continue;
        }
        for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
            AttrId a(at);
            if (s.attr(a).codom != ty) {
                continue;
            }
            ObId dom = s.attr(a).dom;
            std::vector<char> kept_r(rule.R.num_parts(dom), 0);
            for (Part kp = 0; kp < rule.K.num_parts(dom); ++kp) {
                const Value& kv = rule.K.subpart(a, kp);
                if (kv.is_var() && kv.var_index() == k) {
                    kept_r[rule.r(dom, kp)] = 1; // its own cell
                }
            }
            for (Part rp = 0; rp < rule.R.num_parts(dom); ++rp) {
                const Value& cell = rule.R.subpart(a, rp);
                if (cell == rv && !kept_r[rp]) {
                    return true;
                }
            }
        }
    }
    return false;
}

// Whether no hom or attribute of x touches part p of ob: none set from it, none points to it.
bool untouched(const ACSet& x, ObId ob, Part p) {
    const auto& s = x.schema();
    for (HomId f : s.homs_from(ob)) {
        if (x.subpart(f, p) != kNoPart) {
            return false;
        }
    }
    for (AttrId a : s.attrs_from(ob)) {
        if (!x.subpart(a, p).is_unset()) {
            return false;
        }
    }
    for (HomId f : s.homs_into(ob)) {
        if (!x.incident(f, p).empty()) {
            return false;
        }
    }
    return true;
}

} // namespace

std::vector<std::vector<char>> unread_variables(const ACSet& p, const Rule* rule) {
    const auto& s = p.schema();
    std::vector<std::vector<char>> out(s.num_attr_types());
    std::vector<std::vector<int>> count(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        count[t].assign(p.num_vars(AttrTypeId(t)), 0);
    }
    for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
        AttrId a(at);
        for (Part q = 0; q < p.num_parts(s.attr(a).dom); ++q) {
            const Value& v = p.subpart(a, q);
            if (v.is_var()) {
                ++count[s.attr(a).codom.index()][v.var_index()];
            }
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        out[t].assign(p.num_vars(ty), 0);
        for (std::uint32_t v = 0; v < p.num_vars(ty); ++v) {
            bool read = count[t][v] != 1;
            if (rule != nullptr && !read) {
                read = !rule->conditions.empty() || carried(*rule, ty, v);
                for (const auto& per_type : rule->exprs) {
                    for (const auto& e : per_type) {
                        read = read || (e && reads(*e, ty, v));
                    }
                }
            }
            out[t][v] = read ? 0 : 1;
        }
    }
    return out;
}

std::vector<std::vector<char>> loose_parts(const Universe& u, const Rule& rule) {
    const auto& s = u.s;
    std::vector<std::vector<char>> out(s.num_obs());
    bool any = false;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        out[o].assign(rule.L.num_parts(ob), 0);
        if (u.kind[o] == ObKind::Atoms || !rule.conditions.empty()) {
            continue;
        }
        std::vector<Part> k_of_l(rule.L.num_parts(ob), kNoPart);
        for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
            k_of_l[rule.l(ob, k)] = k;
        }
        for (Part l = 0; l < rule.L.num_parts(ob); ++l) {
            Part k = k_of_l[l];
            out[o][l] =
                k != kNoPart && untouched(rule.L, ob, l) && untouched(rule.R, ob, rule.r(ob, k))
                    ? 1
                    : 0;
            any = any || out[o][l] != 0;
        }
    }
    if (!any) {
        out.clear();
    }
    return out;
}

void for_each_match(const Universe& u, const Pattern& pattern,
                    const std::function<bool(const Match&)>& visit) {
    Matcher(u, pattern, visit).run();
}

} // namespace catplan::plan::ground
