#include "catplan/plan/ground/grounding.hpp"

#include "catplan/base/hash.hpp"
#include "catplan/plan/ground/matcher.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>
#include <unordered_map>

namespace catplan::plan::ground {

std::vector<bool> changed_attributes(const Domain& domain) {
    const auto& s = *domain.schema;
    std::vector<bool> changed(s.num_attrs(), false);
    for (const auto& rule : domain.rules) {
        for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
            AttrId a(at);
            ObId dom = s.attr(a).dom;
            AttrTypeId ty = s.attr(a).codom;
            for (Part k = 0; k < rule->K.num_parts(dom); ++k) {
                const Value& rv = rule->R.subpart(a, rule->r(dom, k));
                if (rv.is_unset()) {
                    continue; // R leaves the value as it is
                }
                // Unchanged: a variable passed through K, or the constant L has already.
                const Value& kv = rule->K.subpart(a, k);
                Value in_l = kv.is_var() ? rule->l.var(ty, kv.var_index()) : kv;
                Value in_r = kv.is_var() ? rule->r.var(ty, kv.var_index()) : kv;
                bool passes = rv.is_var() && kv.is_var() && in_r == rv;
                bool same_constant = rv.is_concrete() && in_l == rv;
                if (!passes && !same_constant) {
                    changed[at] = true;
                }
            }
        }
    }
    return changed;
}

namespace {

// What grounding needs to know about a rule, computed once.
struct RuleShape {
    const Rule* rule = nullptr;
    std::uint32_t index = 0;
    std::vector<std::vector<Part>> k_of_l, k_of_r; // per ob, per L (R) part: its K part or kNoPart
    bool never = false; // a kept part refers to a deleted one and the rule does not redirect it
    Pattern pattern;

    bool deleted(ObId ob, Part l) const { return k_of_l[ob.index()][l] == kNoPart; }

    bool created(ObId ob, Part rp) const { return k_of_r[ob.index()][rp] == kNoPart; }

    // Whether kept K part k of dom(f) has f redirected (unset in K, set in R).
    bool redirects(HomId f, Part k) const {
        ObId dom = rule->K.schema().hom(f).dom;
        return rule->K.subpart(f, k) == kNoPart && rule->R.subpart(f, rule->r(dom, k)) != kNoPart;
    }
};

RuleShape shape_of(const Universe& u, const Rule& rule, std::uint32_t index) {
    const auto& s = rule.L.schema();
    RuleShape sh;
    sh.rule = &rule;
    sh.index = index;
    sh.pattern.p = &rule.L;
    sh.pattern.unread = unread_variables(rule.L, &rule);
    sh.pattern.loose = loose_parts(u, rule);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        sh.k_of_l.emplace_back(rule.L.num_parts(ob), kNoPart);
        sh.k_of_r.emplace_back(rule.R.num_parts(ob), kNoPart);
        for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
            sh.k_of_l[o][rule.l(ob, k)] = k;
            sh.k_of_r[o][rule.r(ob, k)] = k;
        }
        sh.pattern.deleted.emplace_back(rule.L.num_parts(ob), 0);
        for (Part l = 0; l < rule.L.num_parts(ob); ++l) {
            sh.pattern.deleted[o][l] = sh.k_of_l[o][l] == kNoPart ? 1 : 0;
        }
    }
    for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
        HomId f(h);
        ObId dom = s.hom(f).dom, cod = s.hom(f).codom;
        for (Part k = 0; k < rule.K.num_parts(dom); ++k) {
            Part t = rule.L.subpart(f, rule.l(dom, k));
            if (t != kNoPart && sh.deleted(cod, t) && !sh.redirects(f, k)) {
                sh.never = true; // the dangling condition fails at every match
            }
        }
    }
    return sh;
}

// A set of facts, one per variable, that refuses contradictions. A sorted vector: drafts are
// copied at every choice while grounding, and a handful of facts copies cheaply.
class Facts {
public:
    bool add(Fact f) {
        auto it = lower(f.var);
        if (it != facts_.end() && it->var == f.var) {
            return it->value == f.value;
        }
        facts_.insert(it, f);
        return true;
    }

    void set(Fact f) {
        auto it = lower(f.var);
        if (it != facts_.end() && it->var == f.var) {
            it->value = f.value;
        } else {
            facts_.insert(it, f);
        }
    }

    std::optional<std::uint32_t> find(VarId v) const {
        auto it = std::lower_bound(facts_.begin(), facts_.end(), v,
                                   [](const Fact& f, VarId x) { return f.var < x; });
        return it == facts_.end() || it->var != v ? std::nullopt
                                                  : std::optional<std::uint32_t>(it->value);
    }

    const std::vector<Fact>& sorted() const { return facts_; }

private:
    std::vector<Fact>::iterator lower(VarId v) {
        return std::lower_bound(facts_.begin(), facts_.end(), v,
                                [](const Fact& f, VarId x) { return f.var < x; });
    }

    std::vector<Fact> facts_; // by variable
};

class Grounder {
public:
    Grounder(Universe& u, const CompileOptions& options)
        : u_(u), s_(u.s), options_(options), task_(u.task) {
        const auto& rules = task_.problem->domain->rules;
        for (std::uint32_t i = 0; i < rules.size(); ++i) {
            shapes_.push_back(shape_of(u, *rules[i], i));
        }
    }

    std::optional<std::string> run() {
        bool changed = true;
        while (changed) {
            changed = false;
            for (const auto& sh : shapes_) {
                if (sh.never) {
                    continue;
                }
                std::vector<Match> found;
                for_each_match(u_, sh.pattern, [&](const Match& m) {
                    if (remember(sh.index, m)) {
                        found.push_back(m);
                    }
                    return true;
                });
                for (const auto& m : found) {
                    changed = add_actions(sh, m) || changed;
                }
                if (auto why = too_large()) {
                    return why;
                }
            }
        }
        return std::nullopt;
    }

private:
    std::optional<std::string> too_large() const {
        if (task_.actions.size() > options_.max_actions) {
            return fmt::format("grounding gives more than {} actions", options_.max_actions);
        }
        if (task_.atoms.size() > options_.max_atoms) {
            return fmt::format("grounding gives more than {} atoms", options_.max_atoms);
        }
        return std::nullopt;
    }

    // Whether this match of rule `rule` is new (and records it).
    bool remember(std::uint32_t rule, const Match& m) {
        std::uint64_t h = hash_mix(rule);
        for (const auto& per_ob : m.images) {
            for (Image c : per_ob) {
                h = hash_combine(h, (std::uint64_t{c.atom} << 32) | c.id);
            }
        }
        for (const auto& per_type : m.bindings) {
            for (const auto& v : per_type) {
                h = hash_combine(h, v.hash());
            }
        }
        auto& bucket = seen_[h];
        for (const auto& [r, images, bindings] : bucket) {
            if (r == rule && bindings == m.bindings &&
                std::equal(images.begin(), images.end(), m.images.begin(),
                           [](const auto& a, const auto& b) {
                               return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                                                 [](Image x, Image y) {
                                                     return x.atom == y.atom && x.id == y.id;
                                                 });
                           })) {
                return false;
            }
        }
        bucket.push_back({rule, m.images, m.bindings});
        return true;
    }

    std::uint32_t pos(HomId f) const { return u_.position[f.index()]; }

    std::uint32_t pos(AttrId a) const { return u_.position[s_.num_homs() + a.index()]; }

    // The value the rule gives R variable j at this match: through K, by an expression, or a
    // fresh unknown; nullopt when an expression fails (the match is no transition).
    std::optional<Value> r_var_value(const Rule& rule, const Match& m, AttrTypeId ty,
                                     std::uint32_t j, bool& through_k) const {
        through_k = false;
        auto bound = [&](const Value& l_value) {
            return l_value.is_var() ? m.bindings[ty.index()][l_value.var_index()] : l_value;
        };
        for (std::uint32_t k = 0; k < rule.K.num_vars(ty); ++k) {
            const Value& rv = rule.r.var(ty, k);
            if (rv.is_var() && rv.var_index() == j) {
                through_k = true;
                return bound(rule.l.var(ty, k));
            }
        }
        const auto& exprs = rule.exprs;
        if (ty.index() < exprs.size() && j < exprs[ty.index()].size() &&
            exprs[ty.index()][j].has_value()) {
            auto v = rewrite::evaluate(*exprs[ty.index()][j], [&](AttrTypeId t, std::uint32_t var) {
                return m.bindings[t.index()][var];
            });
            if (!v) {
                return std::nullopt;
            }
            return *v;
        }
        return kUnknown;
    }

    struct Outcome {
        std::vector<std::vector<Value>> r_values; // per attribute type, per R variable
        std::string exit;                         // an unknown copied to another cell
        bool possible = true;                     // false: an expression fails
    };

    // R's variables at a match, and whether an unknown would end up in a second cell.
    Outcome r_values(const RuleShape& sh, const Match& m) const {
        const Rule& rule = *sh.rule;
        Outcome out;
        out.r_values.resize(s_.num_attr_types());
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            AttrTypeId ty(t);
            for (std::uint32_t j = 0; j < rule.R.num_vars(ty); ++j) {
                bool through_k = false;
                auto v = r_var_value(rule, m, ty, j, through_k);
                if (!v) {
                    out.possible = false;
                    return out;
                }
                out.r_values[t].push_back(*v);
                if (*v == kUnknown && copies_unknown(sh, ty, j, through_k)) {
                    out.exit = "it would put one unknown value in two cells";
                }
            }
        }
        return out;
    }

    // Whether R variable j (an unknown at this match) would be in two cells of the result: in
    // two R cells, or, coming through K from an L cell that survives unchanged, in another cell
    // (moving an unknown is fine, copying it is not).
    bool copies_unknown(const RuleShape& sh, AttrTypeId ty, std::uint32_t j, bool through_k) const {
        const Rule& rule = *sh.rule;
        int cells = 0;
        bool in_place = false;    // its one R cell is the kept cell it came from
        bool origin_kept = false; // an L cell holding it is kept and not rewritten
        for (std::uint32_t at = 0; at < s_.num_attrs(); ++at) {
            AttrId a(at);
            if (s_.attr(a).codom != ty) {
                continue;
            }
            ObId dom = s_.attr(a).dom;
            for (Part rp = 0; rp < rule.R.num_parts(dom); ++rp) {
                const Value& rv = rule.R.subpart(a, rp);
                if (!rv.is_var() || rv.var_index() != j) {
                    continue;
                }
                ++cells;
                Part k = sh.k_of_r[dom.index()][rp];
                const Value kv = k == kNoPart ? Value() : rule.K.subpart(a, k);
                in_place = kv.is_var() && rule.r.var(ty, kv.var_index()) == rv;
            }
            for (Part k = 0; k < rule.K.num_parts(dom); ++k) {
                const Value& kv = rule.K.subpart(a, k);
                if (!kv.is_var()) {
                    continue;
                }
                const Value& rv = rule.r.var(ty, kv.var_index());
                if (rv.is_var() && rv.var_index() == j &&
                    rule.R.subpart(a, rule.r(dom, k)).is_unset()) {
                    origin_kept = true;
                }
            }
        }
        return cells > 1 || (through_k && cells == 1 && !in_place && origin_kept);
    }

    // The value an R attribute cell gives (unset: R leaves it unset).
    static Value r_cell(const Outcome& o, const Value& rv, AttrTypeId ty) {
        if (rv.is_var()) {
            return o.r_values[ty.index()][rv.var_index()];
        }
        return rv;
    }

    // ---- effects ------------------------------------------------------------------------------

    // An effect before its value has a place in its variable's domain (an exit's values are
    // never added: they are not reached).
    struct Effect {
        VarId var;
        bool hom;
        ObjectId target;             // hom
        Value value;                 // attribute
        std::uint32_t index = kNone; // presence and atom variables: the value itself
    };

    struct Draft {
        Facts pre;
        std::vector<Effect> effects; // in order; a later one overrides
        std::vector<VarId> creates;
        std::string exit;
    };

    static void set_index(Draft& d, VarId v, std::uint32_t value) {
        d.effects.push_back({v, false, kNone, Value(), value});
    }

    void set_hom(Draft& d, ObjectId o, HomId f, ObjectId target) {
        const Cell& c = task_.homs[o][pos(f)];
        if (c.var == kNone) {
            if (c.target != target) {
                d.exit = "it changes a value the task keeps fixed";
            }
            return;
        }
        d.effects.push_back({c.var, true, target, Value(), kNone});
    }

    void set_attr(Draft& d, ObjectId o, AttrId a, const Value& v) {
        const Cell& c = task_.attrs[o][pos(a)];
        if (c.var == kNone) {
            if (!(c.value == v)) {
                d.exit = "it changes a value the task keeps fixed";
            }
            return;
        }
        d.effects.push_back({c.var, false, kNone, v, kNone});
    }

    void empty_slot(Draft& d, ObjectId o) {
        const Object& obj = task_.objects[o];
        set_index(d, obj.presence, 0);
        for (HomId f : s_.homs_from(obj.ob)) {
            set_hom(d, o, f, kNone);
        }
        for (AttrId a : s_.attrs_from(obj.ob)) {
            set_attr(d, o, a, Value());
        }
    }

    // The image of every R part: kept parts their L part's, created slot parts their slot,
    // created atom parts kNone (set when their atom is built).
    using RImages = std::vector<std::vector<Image>>;

    RImages kept_images(const RuleShape& sh, const Match& m) const {
        const Rule& rule = *sh.rule;
        RImages out(s_.num_obs());
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            out[o].assign(rule.R.num_parts(ob), Image{});
            for (Part rp = 0; rp < rule.R.num_parts(ob); ++rp) {
                Part k = sh.k_of_r[o][rp];
                if (k != kNoPart) {
                    out[o][rp] = m.images[o][rule.l(ob, k)];
                }
            }
        }
        return out;
    }

    // The atom an R part of an atom object describes, from its image's old values (kept) or
    // nothing (created), with R's hom and attribute values over them.
    Atom r_atom(const RuleShape& sh, const Outcome& o, const RImages& img, ObId ob, Part rp,
                const Atom* old) const {
        const Rule& rule = *sh.rule;
        Atom a = old != nullptr ? *old : Atom{ob, {}, {}, kNone};
        if (old == nullptr) {
            a.homs.assign(s_.homs_from(ob).size(), kNone);
            a.attrs.assign(s_.attrs_from(ob).size(), Value());
        }
        a.var = kNone;
        for (HomId f : s_.homs_from(ob)) {
            Part t = rule.R.subpart(f, rp);
            if (t != kNoPart) {
                a.homs[pos(f)] = img[s_.hom(f).codom.index()][t].id;
            }
        }
        for (AttrId at : s_.attrs_from(ob)) {
            const Value& rv = rule.R.subpart(at, rp);
            Value v = rv.is_unset() ? Value() : r_cell(o, rv, s_.attr(at).codom);
            if (!rv.is_unset() && !(v == kAny)) {
                a.attrs[pos(at)] = v;
            }
        }
        return a;
    }

    // Sets the atom present; unless its object is one of the rule's relations (a fact that
    // holds already is that fact, rule.hpp), it must not be present before.
    void add_atom(Draft& d, Atom a, const Rule& rule) {
        bool relation = std::binary_search(rule.relations.begin(), rule.relations.end(), a.ob);
        AtomId id = u_.intern(std::move(a));
        VarId var = task_.atoms[id].var;
        set_index(d, var, 1);
        if (!relation) {
            d.creates.push_back(var);
        }
    }

    // Values of the parts R touches, once every R part has an image.
    void write_r(Draft& d, const RuleShape& sh, const Match& m, const Outcome& o, RImages& img) {
        const Rule& rule = *sh.rule;
        for (std::uint32_t ob_i = 0; ob_i < s_.num_obs(); ++ob_i) {
            ObId ob(ob_i);
            for (Part rp = 0; rp < rule.R.num_parts(ob); ++rp) {
                bool created = sh.created(ob, rp);
                if (u_.kind[ob_i] == ObKind::Atoms) {
                    const Atom* old = created ? nullptr : &task_.atoms[img[ob_i][rp].id];
                    Atom a = r_atom(sh, o, img, ob, rp, old);
                    if (old != nullptr && a == *old) {
                        continue;
                    }
                    if (old != nullptr) {
                        set_index(d, old->var, 0);
                    }
                    add_atom(d, std::move(a), rule);
                    continue;
                }
                ObjectId id = img[ob_i][rp].id;
                if (created) {
                    set_index(d, task_.objects[id].presence, 1);
                }
                for (HomId f : s_.homs_from(ob)) {
                    Part t = rule.R.subpart(f, rp);
                    if (t != kNoPart) {
                        set_hom(d, id, f, img[s_.hom(f).codom.index()][t].id);
                    } else if (created) {
                        set_hom(d, id, f, kNone);
                    }
                }
                for (AttrId a : s_.attrs_from(ob)) {
                    const Value& rv = rule.R.subpart(a, rp);
                    Value v = rv.is_unset() ? Value() : r_cell(o, rv, s_.attr(a).codom);
                    if (v == kAny) {
                        continue; // an unread variable passed through its own cell: unchanged
                    }
                    if (!rv.is_unset()) {
                        set_attr(d, id, a, v);
                    } else if (created) {
                        set_attr(d, id, a, Value());
                    }
                }
            }
        }
        (void)m;
    }

    // ---- slots for created parts --------------------------------------------------------------

    // Every way to give the created parts of slot objects the lowest free slots (after the
    // deletions); calls `each` with the images filled in and the slot conditions added, or with
    // `exit` set when too few slots are free.
    template <class F>
    void choose_slots(const RuleShape& sh, const Match& m, RImages& img, Draft& d,
                      std::uint32_t ob_i, F&& each) {
        if (ob_i == s_.num_obs()) {
            each(img, d);
            return;
        }
        ObId ob(ob_i);
        std::vector<Part> created;
        for (Part rp = 0; rp < sh.rule->R.num_parts(ob); ++rp) {
            if (sh.created(ob, rp)) {
                created.push_back(rp);
            }
        }
        if (created.empty() || u_.kind[ob_i] != ObKind::Slots) {
            choose_slots(sh, m, img, d, ob_i + 1, each);
            return;
        }
        std::vector<ObjectId> slots;
        for (ObjectId o : task_.objects_of[ob_i]) {
            if (task_.objects[o].is_slot()) {
                slots.push_back(o);
            }
        }
        std::vector<char> deleted(task_.objects.size(), 0);
        for (Part l = 0; l < sh.rule->L.num_parts(ob); ++l) {
            if (sh.deleted(ob, l)) {
                deleted[m.images[ob_i][l].id] = 1;
            }
        }
        // Slot i is free or full after the deletions: decide each slot in order; the chosen
        // ones are the first created.size() free ones.
        std::function<void(std::size_t, std::size_t, Draft)> walk = [&](std::size_t i,
                                                                        std::size_t taken,
                                                                        Draft dd) {
            if (taken == created.size()) {
                choose_slots(sh, m, img, dd, ob_i + 1, each);
                return;
            }
            if (i == slots.size()) {
                dd.exit = fmt::format("it needs a free {} slot and there is none", s_.ob(ob).name);
                each(img, dd);
                return;
            }
            ObjectId o = slots[i];
            VarId pres = task_.objects[o].presence;
            if (deleted[o]) { // free after the deletions: it is taken
                img[ob_i][created[taken]] = Image{false, o};
                walk(i + 1, taken + 1, dd);
                return;
            }
            Draft full = dd;
            if (full.pre.add({pres, 1}) && u_.reached(pres, 1)) {
                walk(i + 1, taken, full);
            }
            if (dd.pre.add({pres, 0}) && u_.reached(pres, 0)) {
                img[ob_i][created[taken]] = Image{false, o};
                walk(i + 1, taken + 1, dd);
            }
        };
        walk(0, 0, d);
    }

    // The ground actions of one new match; whether a fact was reached for the first time.
    bool add_actions(const RuleShape& sh, const Match& m) {
        Outcome o = r_values(sh, m);
        if (!o.possible) {
            return false;
        }
        Draft d;
        for (const Fact& f : m.facts) {
            d.pre.add(f);
        }
        const Rule& rule = *sh.rule;
        for (std::uint32_t ob_i = 0; ob_i < s_.num_obs(); ++ob_i) {
            for (Part l = 0; l < rule.L.num_parts(ObId(ob_i)); ++l) {
                if (!sh.deleted(ObId(ob_i), l)) {
                    continue;
                }
                Image c = m.images[ob_i][l];
                if (c.atom) {
                    set_index(d, task_.atoms[c.id].var, 0);
                } else {
                    empty_slot(d, c.id);
                }
            }
        }
        d.exit = o.exit;
        RImages img = kept_images(sh, m);
        bool fresh = false;
        choose_slots(sh, m, img, d, 0, [&](RImages& images, Draft& dd) {
            Draft out = dd;
            if (out.exit.empty()) {
                write_r(out, sh, m, o, images);
            }
            fresh = record(sh, m, out) || fresh;
        });
        return fresh;
    }

    // Adds the action; reaches its effects (not an exit's); whether any was reached first now.
    bool record(const RuleShape& sh, const Match& m, Draft& d) {
        Action a;
        a.rule = sh.index;
        a.match = m.images;
        a.bindings = m.bindings;
        a.pre = d.pre.sorted();
        a.exit = d.exit;
        if (!cost_of(a)) {
            ++task_.uncosted; // the step cannot be taken: it is no action of the task
            return false;
        }
        bool fresh = false;
        if (a.exit.empty()) {
            Facts eff;
            for (const Effect& e : d.effects) {
                std::uint32_t i = e.index;
                if (i == kNone) {
                    auto [idx, is_new] =
                        e.hom ? u_.hom_value(e.var, e.target) : u_.attr_value(e.var, e.value);
                    i = idx;
                    fresh = fresh || is_new;
                }
                eff.set({e.var, i});
            }
            for (const Fact& f : eff.sorted()) {
                auto p = d.pre.find(f.var);
                if (p && *p == f.value) {
                    continue; // no change
                }
                a.eff.push_back(f);
                const auto kind = task_.vars[f.var].kind;
                if (kind == Variable::Kind::Presence || kind == Variable::Kind::Atom) {
                    fresh = u_.reach_presence(f.var, f.value) || fresh;
                }
            }
            for (VarId v : d.creates) {
                auto p = d.pre.find(v);
                if (!p || *p != 1) {
                    a.creates.push_back(v);
                }
            }
            std::sort(a.creates.begin(), a.creates.end());
            a.creates.erase(std::unique(a.creates.begin(), a.creates.end()), a.creates.end());
        }
        task_.actions.push_back(std::move(a));
        return fresh;
    }

    // Sets a's cost from the problem's step_cost; false when its step has no cost. A cost the
    // search cannot sum is noted in the task (costs_ignored) and the action costs 1.
    bool cost_of(Action& a) {
        const auto& step_cost = task_.problem->step_cost;
        if (!step_cost) {
            return true;
        }
        const Rule& rule = *task_.problem->domain->rules[a.rule];
        auto args = task_.argument_names(a);
        auto c = step_cost(rule, args);
        if (!c) {
            return false;
        }
        if (*c < 0 || *c > kMaxActionCost) {
            if (task_.costs_ignored.empty()) {
                task_.costs_ignored =
                    fmt::format("{}({}) costs {}, and the search sums costs from 0 to {} per step",
                                rule.name, fmt::join(args, ", "), *c, kMaxActionCost);
            }
            return true;
        }
        a.cost = static_cast<int>(*c);
        return true;
    }

    Universe& u_;
    const schema::Schema& s_;
    const CompileOptions& options_;
    Task& task_;
    std::vector<RuleShape> shapes_;

    struct Seen {
        std::uint32_t rule;
        std::vector<std::vector<Image>> images;
        std::vector<std::vector<Value>> bindings;
    };

    std::unordered_map<std::uint64_t, std::vector<Seen>> seen_;
};

} // namespace

std::optional<std::string> ground_actions(Universe& u, const CompileOptions& options) {
    return Grounder(u, options).run();
}

} // namespace catplan::plan::ground
