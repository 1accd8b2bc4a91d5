#include "catplan/plan/ground/plan_back.hpp"

#include "catplan/rewrite/dpo.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::plan::ground {

namespace {

class Replay {
public:
    explicit Replay(const Task& task)
        : task_(task),
          s_(task.problem->initial->schema()),
          x_(*task.problem->initial),
          values_(task.initial) {
        where_.assign(task.objects.size(), kNoPart);
        object_at_.resize(s_.num_obs());
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            object_at_[o].assign(x_.num_parts(ObId(o)), kNone);
        }
        // Entities are their initial parts; the slots of an object take its other initial
        // parts in order, as compile.cpp numbers them.
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            std::vector<ObjectId> slots;
            for (ObjectId id : task.objects_of[o]) {
                const Object& obj = task.objects[id];
                if (obj.is_slot()) {
                    slots.push_back(id);
                } else {
                    place(id, obj.initial);
                }
            }
            std::size_t k = 0;
            for (Part p = 0; p < x_.num_parts(ObId(o)) && k < slots.size(); ++p) {
                if (object_at_[o][p] == kNone) {
                    place(slots[k++], p);
                }
            }
        }
    }

    Result<Step> step(ActionId id) {
        const Action& a = task_.actions[id];
        const Rule& rule = *task_.problem->domain->rules[a.rule];
        auto m = match(a, rule);
        if (!m) {
            return fail(m.error());
        }
        if (auto problem = rewrite::match_problem(rule, x_, *m)) {
            return fail(*problem);
        }
        Step st;
        st.action = rule.name;
        for (const auto& p : rule.parameters) {
            st.args.push_back(x_.part_label(p.ob, (*m)(p.ob, p.part)));
        }
        auto created = created_slots(a, rule);
        track_deletions(rule, *m);
        auto r_to_x = rewrite::rewrite_in_place(rule, x_, *m, rewrite::CheckMatch::No);
        if (!r_to_x) {
            return fail(r_to_x.error());
        }
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            object_at_[o].resize(x_.num_parts(ObId(o)), kNone); // created parts come last
        }
        for (auto [id_obj, ob, rp] : created) {
            place(id_obj, (*r_to_x)(ob, rp));
        }
        for (const Fact& f : a.eff) {
            values_[f.var] = f.value;
        }
        return st;
    }

    const ACSet& state() const { return x_; }

private:
    void place(ObjectId id, Part p) {
        where_[id] = p;
        object_at_[task_.objects[id].ob.index()][p] = id;
    }

    // The X part an atom is at now.
    std::optional<Part> find_atom(const Atom& at) const {
        for (Part p = 0; p < x_.num_parts(at.ob); ++p) {
            std::size_t i = 0;
            bool same = true;
            for (HomId f : s_.homs_from(at.ob)) {
                Part t = x_.subpart(f, p);
                ObjectId o = t == kNoPart ? kNone : object_at_[s_.hom(f).codom.index()][t];
                same = same && o == at.homs[i++];
            }
            i = 0;
            for (AttrId a : s_.attrs_from(at.ob)) {
                const Value& v = x_.subpart(a, p);
                same = same && (v.is_var() ? kUnknown : v) == at.attrs[i++];
            }
            if (same) {
                return p;
            }
        }
        return std::nullopt;
    }

    Result<hom::ACSetMorphism> match(const Action& a, const Rule& rule) const {
        hom::ACSetMorphism m;
        m.components.resize(s_.num_obs());
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            for (Part l = 0; l < rule.L.num_parts(ObId(o)); ++l) {
                Image c = a.match[o][l];
                Part x = kNoPart;
                if (c.atom) {
                    auto p = find_atom(task_.atoms[c.id]);
                    if (!p) {
                        return fail(fmt::format("{} is not in the state",
                                                task_.describe(task_.atoms[c.id].var)));
                    }
                    x = *p;
                } else {
                    x = where_[c.id];
                }
                if (x == kNoPart) {
                    return fail(fmt::format("{} is empty", task_.object_name(c.id)));
                }
                m.components[o].push_back(x);
            }
        }
        // Each L variable: the value of an L cell holding it, at its image.
        m.var_components.resize(s_.num_attr_types());
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            m.var_components[t].assign(rule.L.num_vars(AttrTypeId(t)), Value());
        }
        for (std::uint32_t at = 0; at < s_.num_attrs(); ++at) {
            AttrId attr(at);
            ObId dom = s_.attr(attr).dom;
            auto ty = s_.attr(attr).codom.index();
            for (Part l = 0; l < rule.L.num_parts(dom); ++l) {
                const Value& lv = rule.L.subpart(attr, l);
                if (lv.is_var()) {
                    m.var_components[ty][lv.var_index()] =
                        x_.subpart(attr, m.components[dom.index()][l]);
                }
            }
        }
        return m;
    }

    struct Created {
        ObjectId slot;
        ObId ob;
        Part rp;
    };

    // The slots the created parts of slot objects take: the lowest free ones after the
    // deletions, in R's order (as grounding.cpp chooses them).
    std::vector<Created> created_slots(const Action& a, const Rule& rule) const {
        std::vector<Created> out;
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            std::vector<char> kept_r(rule.R.num_parts(ob), 0);
            for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
                kept_r[rule.r(ob, k)] = 1;
            }
            std::vector<char> freed(task_.objects.size(), 0);
            std::vector<char> kept_l(rule.L.num_parts(ob), 0);
            for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
                kept_l[rule.l(ob, k)] = 1;
            }
            for (Part l = 0; l < rule.L.num_parts(ob); ++l) {
                if (!kept_l[l] && !a.match[o][l].atom) {
                    freed[a.match[o][l].id] = 1;
                }
            }
            std::vector<ObjectId> free;
            for (ObjectId id : task_.objects_of[o]) {
                const Object& obj = task_.objects[id];
                if (obj.is_slot() && (freed[id] || values_[obj.presence] == 0)) {
                    free.push_back(id);
                }
            }
            std::size_t next = 0;
            for (Part rp = 0; rp < rule.R.num_parts(ob); ++rp) {
                if (!kept_r[rp] && !task_.objects_of[o].empty()) {
                    CATPLAN_ASSERT(next < free.size(), "a planned action without a free slot");
                    out.push_back({free[next++], ob, rp});
                }
            }
        }
        return out;
    }

    // Pop-and-swap of the deleted parts, in the order rewrite_in_place deletes them.
    void track_deletions(const Rule& rule, const hom::ACSetMorphism& m) {
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            std::vector<char> kept_l(rule.L.num_parts(ob), 0);
            for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
                kept_l[rule.l(ob, k)] = 1;
            }
            std::vector<Part> deleted;
            for (Part l = 0; l < rule.L.num_parts(ob); ++l) {
                if (!kept_l[l]) {
                    deleted.push_back(m(ob, l));
                }
            }
            std::sort(deleted.begin(), deleted.end());
            deleted.erase(std::unique(deleted.begin(), deleted.end()), deleted.end());
            auto& at = object_at_[o];
            for (auto it = deleted.rbegin(); it != deleted.rend(); ++it) {
                Part y = *it;
                if (at[y] != kNone) {
                    where_[at[y]] = kNoPart;
                }
                Part last = static_cast<Part>(at.size() - 1);
                if (last != y) {
                    at[y] = at[last];
                    if (at[y] != kNone) {
                        where_[at[y]] = y;
                    }
                }
                at.pop_back();
            }
        }
    }

    const Task& task_;
    const schema::Schema& s_;
    ACSet x_;
    std::vector<std::uint32_t> values_;
    std::vector<Part> where_;                      // per object: its part now (kNoPart: empty)
    std::vector<std::vector<ObjectId>> object_at_; // per ob, per part: its object (or kNone)
};

} // namespace

Result<Plan> to_dpo_plan(const Task& task, const std::vector<ActionId>& plan,
                         std::optional<ACSet>* last) {
    Replay replay(task);
    Plan out;
    for (std::size_t i = 0; i < plan.size(); ++i) {
        auto st = replay.step(plan[i]);
        if (!st) {
            return fail(
                fmt::format("step {} {}: {}", i + 1, task.describe_action(plan[i]), st.error()));
        }
        out.steps.push_back(std::move(*st));
    }
    if (last != nullptr) {
        *last = replay.state();
    }
    return out;
}

} // namespace catplan::plan::ground
