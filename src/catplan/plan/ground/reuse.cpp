#include "catplan/plan/ground/reuse.hpp"

#include "catplan/plan/entities.hpp"
#include "catplan/plan/ground/ground_search.hpp"
#include "catplan/plan/ground/universe.hpp"

#include <fmt/format.h>

namespace catplan::plan::ground {

namespace {

// The value a state's attribute cell has in the task: its constant, kUnknown for a variable (as
// compile.cpp writes the first state).
Value task_value(const Value& v) {
    return v.is_var() ? kUnknown : v;
}

std::uint32_t find_target(const Variable& v, ObjectId target) {
    for (std::uint32_t i = 0; i < v.targets.size(); ++i) {
        if (v.targets[i] == target) {
            return i;
        }
    }
    return kNone;
}

std::uint32_t find_value(const Variable& v, const Value& value) {
    for (std::uint32_t i = 0; i < v.values.size(); ++i) {
        if (v.values[i] == value) {
            return i;
        }
    }
    return kNone;
}

// Whether nothing points into ob and not every part of it is an entity: its parts are atoms
// (compile.cpp's classification).
bool atom_object(const schema::Schema& s, const Entities& e, ObId ob) {
    return !e.whole[ob.index()] && s.homs_into(ob).empty();
}

} // namespace

Result<ReusableTask> ReusableTask::compile(const ProblemPtr& problem, const SearchOptions& options,
                                           const CompileOptions& compile_options) {
    Budget budget(options.limits(), Clock::now());
    ReusableTask out;
    try {
        auto task = ground::compile(problem, budget, compile_options);
        if (!task) {
            return fail(task.error());
        }
        out.task_ = std::make_unique<Task>(std::move(*task));
    } catch (const LimitReached& stop) {
        return fail(
            fmt::format("compiling the ground task reached the {}", to_string(stop.status)));
    }
    out.compile_seconds_ = budget.elapsed();
    const Task& t = *out.task_;
    const ACSet& x = *problem->initial;
    out.by_name_.resize(x.schema().num_obs());
    for (ObjectId id = 0; id < t.objects.size(); ++id) {
        const Object& obj = t.objects[id];
        std::string_view name =
            obj.is_slot() ? std::string_view() : x.part_name(obj.ob, obj.initial);
        out.names_.push_back(name);
        if (!name.empty()) {
            auto [it, fresh] = out.by_name_[obj.ob.index()].emplace(name, id);
            if (!fresh) {
                it->second = kNone; // a name two entities share names neither
            }
        }
    }
    for (AtomId a = 0; a < t.atoms.size(); ++a) {
        out.atom_index_[atom_hash(t.atoms[a])].push_back(a);
    }
    out.atom_ob_.resize(x.schema().num_obs());
    auto entities = find_entities(*problem->domain, x);
    for (std::uint32_t o = 0; o < x.schema().num_obs(); ++o) {
        out.atom_ob_[o] = atom_object(x.schema(), entities, ObId(o)) ? 1 : 0;
    }
    return out;
}

AtomId ReusableTask::find_atom(const Atom& a) const {
    auto it = atom_index_.find(atom_hash(a));
    if (it != atom_index_.end()) {
        for (AtomId id : it->second) {
            if (task_->atoms[id] == a) {
                return id;
            }
        }
    }
    return kNone;
}

Result<SearchResult> ReusableTask::search(std::shared_ptr<const ACSet> initial,
                                          std::shared_ptr<const ACSet> goal,
                                          const SearchOptions& options) {
    CATPLAN_ASSERT(initial && goal && &initial->schema() == &task_->problem->initial->schema(),
                   "a reused task searches states on its problem's schema");
    Budget budget(options.limits(), options.start.value_or(Clock::now()));
    if (auto why = write_initial(*initial)) {
        return fail(*why);
    }
    bool unreachable = false;
    if (auto why = write_goal(*goal, unreachable)) {
        return fail(*why);
    }
    auto problem = std::make_shared<Problem>(*task_->problem);
    problem->initial = std::move(initial);
    problem->goal = std::move(goal);
    task_->problem = std::move(problem);
    GroundOutcome out;
    out.result.path = "grounded";
    out.result.path_reason = "the ground task compiled before, from another initial state";
    if (unreachable) {
        out.result.status = SearchStatus::Unsolvable;
        out.result.config = "the goal by names has a fact the task never reaches";
        return std::move(out.result);
    }
    search_task(*task_, options, budget, out);
    if (!out.rejected.empty()) {
        return fail("the plan found was rejected: " + out.rejected);
    }
    return std::move(out.result);
}

// ---- writing a state in the task's variables ----------------------------------------------------

std::optional<std::string> ReusableTask::write_initial(const ACSet& x) {
    Task& t = *task_;
    const auto& s = x.schema();
    for (std::uint32_t ty = 0; ty < s.num_attr_types(); ++ty) {
        for (std::uint32_t j = 0; j < x.num_vars(AttrTypeId(ty)); ++j) {
            if (x.var_incident(AttrTypeId(ty), j).size() > 1) {
                return fmt::format("the state has an unknown {} in two cells",
                                   x.value_label(AttrTypeId(ty), Value::var(j)));
            }
        }
    }
    std::vector<std::vector<ObjectId>> object_of(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!atom_ob_[o]) {
            if (auto why = place_parts(x, object_of[o], ObId(o))) {
                return why;
            }
        }
    }
    std::vector<std::uint32_t> values(t.vars.size(), 0);
    std::vector<char> present(t.objects.size(), 0);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < object_of[o].size(); ++p) {
            ObjectId id = object_of[o][p];
            present[id] = 1;
            if (auto why = write_cells(x, ObId(o), p, id, object_of, values)) {
                return why;
            }
        }
        if (atom_ob_[o]) {
            if (auto why = write_atoms(x, ObId(o), object_of, values)) {
                return why;
            }
        }
    }
    // An empty slot: absent, its cells unset where the task has that value.
    for (ObjectId id = 0; id < t.objects.size(); ++id) {
        if (present[id] || !t.objects[id].is_slot()) {
            continue;
        }
        for (const Cell& c : t.homs[id]) {
            if (c.var != kNone) {
                std::uint32_t i = find_target(t.vars[c.var], kNone);
                values[c.var] = i == kNone ? 0 : i;
            }
        }
        for (const Cell& c : t.attrs[id]) {
            if (c.var != kNone) {
                std::uint32_t i = find_value(t.vars[c.var], Value());
                values[c.var] = i == kNone ? 0 : i;
            }
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < object_of[o].size(); ++p) {
            Object& obj = t.objects[object_of[o][p]];
            if (obj.is_slot()) {
                values[obj.presence] = 1;
            } else {
                obj.initial = p;
            }
        }
    }
    t.initial = std::move(values);
    return std::nullopt;
}

// The object of each part of ob (not an atom object): its entity, by name (or by number when the
// names agree place by place), else the next slot.
std::optional<std::string>
ReusableTask::place_parts(const ACSet& x, std::vector<ObjectId>& object_of, ObId ob) const {
    const Task& t = *task_;
    const auto& ids = t.objects_of[ob.index()];
    const auto& s = x.schema();
    object_of.assign(x.num_parts(ob), kNone);
    std::vector<ObjectId> slots;
    for (ObjectId id : ids) {
        if (t.objects[id].is_slot()) {
            slots.push_back(id);
        }
    }
    bool same = slots.empty() && x.num_parts(ob) == ids.size();
    for (Part p = 0; same && p < ids.size(); ++p) {
        same = names_[ids[p]] == x.part_name(ob, p);
        object_of[p] = ids[p];
    }
    if (same) {
        return std::nullopt;
    }
    std::vector<char> used(t.objects.size(), 0);
    std::size_t entities = 0;
    const auto& by_name = by_name_[ob.index()];
    for (Part p = 0; p < x.num_parts(ob); ++p) {
        object_of[p] = kNone;
        std::string_view name = x.part_name(ob, p);
        auto it = name.empty() ? by_name.end() : by_name.find(name);
        if (it != by_name.end() && it->second != kNone && !used[it->second]) {
            object_of[p] = it->second;
            used[it->second] = 1;
            ++entities;
        }
    }
    if (entities + slots.size() != ids.size()) {
        return fmt::format("an entity of {} is not in the state (or not by its name)",
                           s.ob(ob).name);
    }
    std::size_t k = 0;
    for (Part p = 0; p < x.num_parts(ob); ++p) {
        if (object_of[p] == kNone) {
            if (k == slots.size()) {
                return fmt::format("the state has more parts of {} than the task has slots",
                                   s.ob(ob).name);
            }
            object_of[p] = slots[k++];
        }
    }
    return std::nullopt;
}

// The hom and attribute values of part p (object o), static ones checked.
std::optional<std::string>
ReusableTask::write_cells(const ACSet& x, ObId ob, Part p, ObjectId o,
                          const std::vector<std::vector<ObjectId>>& object_of,
                          std::vector<std::uint32_t>& values) const {
    const Task& t = *task_;
    const auto& s = x.schema();
    auto homs = s.homs_from(ob);
    for (std::size_t i = 0; i < homs.size(); ++i) {
        Part q = x.subpart(homs[i], p);
        ObjectId target = q == kNoPart ? kNone : object_of[s.hom(homs[i]).codom.index()][q];
        const Cell& c = t.homs[o][i];
        std::uint32_t v = c.var == kNone ? kNone : find_target(t.vars[c.var], target);
        if (c.var == kNone ? c.target != target : v == kNone) {
            return fmt::format("{}({}) has a value the task never reaches", s.hom(homs[i]).name,
                               x.part_label(ob, p));
        }
        if (c.var != kNone) {
            values[c.var] = v;
        }
    }
    auto attrs = s.attrs_from(ob);
    for (std::size_t i = 0; i < attrs.size(); ++i) {
        Value value = task_value(x.subpart(attrs[i], p));
        const Cell& c = t.attrs[o][i];
        std::uint32_t v = c.var == kNone ? kNone : find_value(t.vars[c.var], value);
        if (c.var == kNone ? c.value != value : v == kNone) {
            return fmt::format("{}({}) has a value the task never reaches", s.attr(attrs[i]).name,
                               x.part_label(ob, p));
        }
        if (c.var != kNone) {
            values[c.var] = v;
        }
    }
    return std::nullopt;
}

// The atoms of the state's parts of ob, each one the task interned.
std::optional<std::string>
ReusableTask::write_atoms(const ACSet& x, ObId ob,
                          const std::vector<std::vector<ObjectId>>& object_of,
                          std::vector<std::uint32_t>& values) const {
    const Task& t = *task_;
    const auto& s = x.schema();
    for (Part p = 0; p < x.num_parts(ob); ++p) {
        Atom a{ob, {}, {}, kNone};
        for (HomId f : s.homs_from(ob)) {
            Part q = x.subpart(f, p);
            a.homs.push_back(q == kNoPart ? kNone : object_of[s.hom(f).codom.index()][q]);
        }
        for (AttrId at : s.attrs_from(ob)) {
            a.attrs.push_back(task_value(x.subpart(at, p)));
        }
        AtomId id = find_atom(a);
        if (id == kNone) {
            return fmt::format("the state's {} {} is never reached by the task", s.ob(ob).name,
                               x.part_label(ob, p));
        }
        VarId var = t.atoms[id].var;
        if (values[var] == 1) {
            return fmt::format("the state has two equal {} parts", s.ob(ob).name);
        }
        values[var] = 1;
    }
    return std::nullopt;
}

// ---- writing a goal by names --------------------------------------------------------------------

std::optional<std::string> ReusableTask::goal_object(const ACSet& g, ObId ob, Part p,
                                                     ObjectId& o) const {
    std::string_view name = g.part_name(ob, p);
    const auto& by_name = by_name_[ob.index()];
    auto it = name.empty() ? by_name.end() : by_name.find(name);
    if (it == by_name.end() || it->second == kNone) {
        return fmt::format("the goal's {} {} is no entity of the task by name",
                           g.schema().ob(ob).name, g.part_label(ob, p));
    }
    o = it->second;
    return std::nullopt;
}

void ReusableTask::goal_fact(VarId var, std::uint32_t value, bool& unreachable) {
    auto [it, fresh] = goal_facts_.emplace(var, value);
    unreachable = unreachable || value == kNone || (!fresh && it->second != value);
}

std::optional<std::string> ReusableTask::write_goal(const ACSet& g, bool& unreachable) {
    Task& t = *task_;
    const auto& s = g.schema();
    goal_facts_.clear();
    std::vector<std::vector<ObjectId>> object_of(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (atom_ob_[o]) {
            continue;
        }
        for (Part p = 0; p < g.num_parts(ObId(o)); ++p) {
            ObjectId id = kNone;
            if (auto why = goal_object(g, ObId(o), p, id)) {
                return why;
            }
            object_of[o].push_back(id);
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < g.num_parts(ob); ++p) {
            if (atom_ob_[o]) {
                Atom a{ob, {}, {}, kNone};
                for (HomId f : s.homs_from(ob)) {
                    Part q = g.subpart(f, p);
                    a.homs.push_back(q == kNoPart ? kNone : object_of[s.hom(f).codom.index()][q]);
                }
                for (AttrId at : s.attrs_from(ob)) {
                    if (!g.subpart(at, p).is_concrete()) {
                        return "the goal has a fact with an unknown value";
                    }
                    a.attrs.push_back(g.subpart(at, p));
                }
                AtomId id = find_atom(a);
                if (id == kNone) {
                    unreachable = true;
                } else {
                    goal_fact(t.atoms[id].var, 1, unreachable);
                }
                continue;
            }
            ObjectId id = object_of[o][p];
            auto homs = s.homs_from(ob);
            for (std::size_t i = 0; i < homs.size(); ++i) {
                Part q = g.subpart(homs[i], p);
                if (q == kNoPart) {
                    continue; // unset in a goal: any value
                }
                ObjectId target = object_of[s.hom(homs[i]).codom.index()][q];
                const Cell& c = t.homs[id][i];
                if (c.var == kNone) {
                    unreachable = unreachable || c.target != target;
                } else {
                    goal_fact(c.var, find_target(t.vars[c.var], target), unreachable);
                }
            }
            auto attrs = s.attrs_from(ob);
            for (std::size_t i = 0; i < attrs.size(); ++i) {
                const Value& value = g.subpart(attrs[i], p);
                if (!value.is_concrete()) {
                    continue; // an unknown or unset value in a goal: any value
                }
                const Cell& c = t.attrs[id][i];
                if (c.var == kNone) {
                    unreachable = unreachable || c.value != value;
                } else {
                    goal_fact(c.var, find_value(t.vars[c.var], value), unreachable);
                }
            }
        }
    }
    std::vector<Fact> term;
    for (auto [var, value] : goal_facts_) {
        term.push_back({var, value});
    }
    t.goal = {std::move(term)};
    return std::nullopt;
}

} // namespace catplan::plan::ground
