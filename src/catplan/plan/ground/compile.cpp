// The ground compiler's driver and its first two steps (compile.hpp): which objects, slots and
// atoms there are, and the initial state in those terms.

#include "catplan/plan/ground/compile.hpp"

#include "catplan/plan/ground/grounding.hpp"
#include "catplan/plan/ground/mutexes.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::plan::ground {

namespace {

std::optional<std::string> unsupported(const Domain& d) {
    const auto& s = *d.schema;
    for (const auto& rule : d.rules) {
        if (rule->semantics == rewrite::Semantics::SPO) {
            return fmt::format("rule {} deletes dangling parts (SPO)", rule->name);
        }
        for (const auto& c : rule->conditions) {
            if (!c.negative) {
                return fmt::format("rule {} has a positive application condition", rule->name);
            }
        }
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            std::vector<char> hit(rule->R.num_parts(ObId(o)), 0);
            for (Part k = 0; k < rule->K.num_parts(ObId(o)); ++k) {
                if (hit[rule->r(ObId(o), k)]++) {
                    return fmt::format("rule {} glues kept parts of {}", rule->name,
                                       s.ob(ObId(o)).name);
                }
            }
        }
    }
    return std::nullopt;
}

// The value a state's attribute cell has in the task: its constant, kUnknown for a variable.
Value task_value(const Value& v) {
    return v.is_var() ? kUnknown : v;
}

class SetUp {
public:
    SetUp(Universe& u) : u_(u), s_(u.s), x_(*u.task.problem->initial) {}

    std::optional<std::string> run() {
        if (auto why = shared_unknown()) {
            return why;
        }
        classify();
        if (auto why = make_objects()) {
            return why;
        }
        set_cells();
        return make_atoms();
    }

private:
    std::optional<std::string> shared_unknown() const {
        for (std::uint32_t t = 0; t < s_.num_attr_types(); ++t) {
            for (std::uint32_t j = 0; j < x_.num_vars(AttrTypeId(t)); ++j) {
                if (x_.var_incident(AttrTypeId(t), j).size() > 1) {
                    return fmt::format("the initial state has an unknown {} in two cells",
                                       x_.value_label(AttrTypeId(t), Value::var(j)));
                }
            }
        }
        return std::nullopt;
    }

    void classify() {
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            if (u_.entities.whole[o]) {
                u_.kind[o] = ObKind::Entities;
            } else if (!s_.homs_into(ob).empty()) {
                u_.kind[o] = ObKind::Slots;
            } else {
                u_.kind[o] = ObKind::Atoms;
            }
        }
    }

    // The most parts of ob one rule creates.
    std::size_t most_created(ObId ob) const {
        std::size_t most = 0;
        for (const auto& rule : u_.task.problem->domain->rules) {
            std::size_t n = rule->R.num_parts(ob) - rule->K.num_parts(ob);
            most = std::max(most, n);
        }
        return most;
    }

    std::optional<std::string> make_objects() {
        object_of_.resize(s_.num_obs());
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            object_of_[o].assign(x_.num_parts(ob), kNone);
            if (u_.kind[o] == ObKind::Atoms) {
                continue;
            }
            if (u_.kind[o] == ObKind::Slots && !u_.entities.stable[o]) {
                return fmt::format("a rule merges parts of {}", s_.ob(ob).name);
            }
            std::vector<Part> others;
            for (Part p = 0; p < x_.num_parts(ob); ++p) {
                if (u_.entities.is_entity(ob, p)) {
                    object_of_[o][p] = u_.add_object(ob, p, 0);
                } else {
                    others.push_back(p);
                }
            }
            std::size_t slots = std::max(others.size(), most_created(ob));
            for (std::uint32_t k = 0; k < slots; ++k) {
                ObjectId id = u_.add_object(ob, kNoPart, k);
                if (k < others.size()) {
                    object_of_[o][others[k]] = id;
                    slot_part_.emplace_back(id, others[k]);
                }
            }
        }
        return std::nullopt;
    }

    // Per object its hom and attribute values (static for entities where no rule changes them).
    void set_cells() {
        auto changed = changed_attributes(*u_.task.problem->domain);
        u_.initial_values.assign(u_.task.vars.size(), 0);
        std::vector<Part> part_of(u_.task.objects.size(), kNoPart);
        for (std::uint32_t id = 0; id < u_.task.objects.size(); ++id) {
            part_of[id] = u_.task.objects[id].initial;
        }
        for (auto [id, p] : slot_part_) {
            part_of[id] = p;
        }
        for (ObjectId id = 0; id < u_.task.objects.size(); ++id) {
            const Object& obj = u_.task.objects[id];
            Part p = part_of[id];
            for (HomId f : s_.homs_from(obj.ob)) {
                Part t = p == kNoPart ? kNoPart : x_.subpart(f, p);
                ObjectId target = t == kNoPart ? kNone : object_of_[s_.hom(f).codom.index()][t];
                u_.set_static_hom(id, f, target);
                if (obj.is_slot() || u_.entities.redirected[f.index()]) {
                    u_.make_dynamic_hom(id, f);
                }
            }
            for (AttrId a : s_.attrs_from(obj.ob)) {
                Cell& c = u_.task.attrs[id][u_.position[s_.num_homs() + a.index()]];
                c.value = p == kNoPart ? Value() : task_value(x_.subpart(a, p));
                if (obj.is_slot() || changed[a.index()]) {
                    u_.make_dynamic_attr(id, a);
                }
            }
            if (obj.is_slot()) {
                u_.reach_presence(obj.presence, p != kNoPart ? 1 : 0);
            }
        }
        u_.initial_values.assign(u_.task.vars.size(), 0);
        for (ObjectId id = 0; id < u_.task.objects.size(); ++id) {
            const Object& obj = u_.task.objects[id];
            if (obj.is_slot()) {
                u_.initial_values[obj.presence] = part_of[id] != kNoPart ? 1 : 0;
            }
        }
    }

    std::optional<std::string> make_atoms() {
        for (std::uint32_t o = 0; o < s_.num_obs(); ++o) {
            ObId ob(o);
            if (u_.kind[o] != ObKind::Atoms) {
                continue;
            }
            for (Part p = 0; p < x_.num_parts(ob); ++p) {
                Atom a{ob, {}, {}, kNone};
                for (HomId f : s_.homs_from(ob)) {
                    Part t = x_.subpart(f, p);
                    a.homs.push_back(t == kNoPart ? kNone : object_of_[s_.hom(f).codom.index()][t]);
                }
                for (AttrId at : s_.attrs_from(ob)) {
                    a.attrs.push_back(task_value(x_.subpart(at, p)));
                }
                AtomId id = u_.intern(std::move(a));
                VarId var = u_.task.atoms[id].var;
                u_.initial_values.resize(u_.task.vars.size(), 0);
                if (u_.initial_values[var] == 1) {
                    return fmt::format("the initial state has two equal {} parts ({} and another)",
                                       s_.ob(ob).name, x_.part_label(ob, p));
                }
                u_.initial_values[var] = 1;
                u_.reach_presence(var, 1);
            }
        }
        return std::nullopt;
    }

    Universe& u_;
    const schema::Schema& s_;
    const ACSet& x_;
    std::vector<std::vector<ObjectId>> object_of_; // per ob, per initial part
    std::vector<std::pair<ObjectId, Part>> slot_part_;
};

// Whether the actions' costs are all 1; a cost the search cannot sum makes every action cost 1.
void settle_costs(Task& task) {
    if (!task.costs_ignored.empty()) {
        for (Action& a : task.actions) {
            a.cost = 1;
        }
    }
    task.unit_cost = std::all_of(task.actions.begin(), task.actions.end(),
                                 [](const Action& a) { return a.cost == 1; });
}

} // namespace

Result<Task> compile(const ProblemPtr& problem, Budget& budget, const CompileOptions& options) {
    CATPLAN_ASSERT(problem && problem->initial && problem->domain, "compile needs a problem");
    if (auto why = unsupported(*problem->domain)) {
        return fail(*why);
    }
    Task task;
    task.problem = problem;
    auto entities = find_entities(*problem->domain, *problem->initial);
    Universe u(task, entities, budget);
    if (auto why = SetUp(u).run()) {
        return fail(*why);
    }
    if (auto why = ground_actions(u, options)) {
        return fail(*why);
    }
    finish_actions(u);
    settle_costs(task);
    if (auto why = ground_goal(u, options)) {
        return fail(*why);
    }
    task.initial = u.initial_values;
    task.initial.resize(task.vars.size(), 0);
    if (options.mutexes) {
        task.mutex_groups = find_mutex_groups(task, budget);
    }
    return task;
}

} // namespace catplan::plan::ground
