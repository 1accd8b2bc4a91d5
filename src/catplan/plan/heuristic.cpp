#include "catplan/plan/heuristic.hpp"

#include "catplan/base/hash.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/plan/entities.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>
#include <unordered_set>

namespace catplan::plan {

std::optional<HeuristicKind> parse_heuristic(std::string_view name) {
    if (name == "default") {
        return HeuristicKind::Default;
    }
    if (name == "hmax") {
        return HeuristicKind::HMax;
    }
    if (name == "lmcut") {
        return HeuristicKind::LmCut;
    }
    if (name == "lmcount") {
        return HeuristicKind::LmCount;
    }
    if (name == "blind") {
        return HeuristicKind::Blind;
    }
    if (name == "goalcount") {
        return HeuristicKind::GoalCount;
    }
    if (name == "hadd") {
        return HeuristicKind::HAdd;
    }
    if (name == "hff") {
        return HeuristicKind::HFF;
    }
    return std::nullopt;
}

std::string_view to_string(HeuristicKind kind) {
    switch (kind) {
    case HeuristicKind::Default:
        return "default";
    case HeuristicKind::HMax:
        return "hmax";
    case HeuristicKind::LmCut:
        return "lmcut";
    case HeuristicKind::LmCount:
        return "lmcount";
    case HeuristicKind::Blind:
        return "blind";
    case HeuristicKind::GoalCount:
        return "goalcount";
    case HeuristicKind::HAdd:
        return "hadd";
    case HeuristicKind::HFF:
        return "hff";
    }
    CATPLAN_UNREACHABLE("heuristic kind");
}

namespace {

using acset::Value;

// One position of a fact: unknown (a wildcard), an entity slot of a rule, or a known value (an
// entity's part id or an attribute value's hash).
struct Pos {
    enum class Kind : std::uint8_t { Wild, Slot, Const };
    Kind kind = Kind::Wild;
    std::uint64_t value = 0;

    friend bool operator==(const Pos&, const Pos&) = default;
};

struct Fact {
    std::uint32_t type = 0;
    std::vector<Pos> pos;

    friend bool operator==(const Fact&, const Fact&) = default;
};

std::uint64_t mask_of(const Fact& f) {
    std::uint64_t m = 0;
    for (std::size_t i = 0; i < f.pos.size() && i < 64; ++i) {
        if (f.pos[i].kind != Pos::Kind::Wild) {
            m |= std::uint64_t{1} << i;
        }
    }
    return m;
}

// The key of a fact's projection onto a mask (all Const at the mask's positions).
std::uint64_t key_of(std::uint32_t type, std::uint64_t mask, const std::vector<Pos>& pos) {
    std::uint64_t h = hash_combine(hash_mix(type), mask);
    for (std::size_t i = 0; i < pos.size() && i < 64; ++i) {
        if (mask >> i & 1) {
            h = hash_combine(h, pos[i].value);
        }
    }
    return h;
}

// The fact abstraction of a problem and its ground relaxed actions (heuristic.hpp).
class RelaxedTask {
public:
    RelaxedTask(const Problem& problem, Budget* budget)
        : schema_(problem.initial->schema_ptr()), budget_(budget) {
        classify(problem);
        // Templates of every rule, and the goal's facts; their masks are the projections in use.
        for (const auto& rule : problem.domain->rules) {
            templates_.push_back(make_template(*rule));
        }
        // One list of goal facts per way of identifying the goal's entities (see goal_entities).
        std::vector<std::vector<Fact>> goal_facts;
        if (problem.goal) {
            const ACSet& g = *problem.goal;
            for (const auto& image : goal_entities(g, *problem.initial)) {
                goal_facts.push_back(facts_of(g, [&](ObId ob, Part p) -> std::optional<Pos> {
                    Part q = image[ob.index()][p];
                    return q != kNoPart ? Pos{Pos::Kind::Const, q} : Pos{};
                }));
            }
        }
        masks_.assign(num_types(), {});
        for (const auto& t : templates_) {
            for (const auto& f : t.pre) {
                add_mask(f);
            }
        }
        for (const auto& facts : goal_facts) {
            for (const auto& f : facts) {
                add_mask(f);
            }
        }
        // Types some rule adds to; the others keep their initial facts forever.
        dynamic_.assign(num_types(), false);
        for (const auto& t : templates_) {
            for (const auto& f : t.add) {
                dynamic_[f.type] = true;
            }
        }
        for (const auto& f : state_facts(*problem.initial)) {
            if (!dynamic_[f.type]) {
                for (std::uint64_t m : masks_[f.type]) {
                    if ((mask_of(f) & m) == m) {
                        initial_static_.insert(key_of(f.type, m, f.pos));
                    }
                }
            }
        }
        for (const auto& facts : goal_facts) {
            std::vector<std::uint32_t> goal;
            for (const auto& f : facts) {
                goal.push_back(prop(key_of(f.type, mask_of(f), f.pos)));
            }
            std::sort(goal.begin(), goal.end());
            goal.erase(std::unique(goal.begin(), goal.end()), goal.end());
            goals_.push_back(std::move(goal));
        }
        ground();
    }

    std::size_t num_props() const { return num_props_; }

    // Lets a long evaluation stop at a limit (throws LimitReached).
    void poll() const {
        if (budget_ != nullptr) {
            budget_->poll();
        }
    }

    // The goal's props, one list per identification of its entities; h is the least over them.
    const std::vector<std::vector<std::uint32_t>>& goals() const { return goals_; }

    // The props true in x (projections of its facts that some precondition or goal uses).
    void props_of(const ACSet& x, std::vector<char>& truth) const {
        truth.assign(num_props_, 0);
        for (const auto& f : state_facts(x)) {
            std::uint64_t fm = mask_of(f);
            for (std::uint64_t m : masks_[f.type]) {
                if ((fm & m) == m) {
                    auto it = props_.find(key_of(f.type, m, f.pos));
                    if (it != props_.end()) {
                        truth[it->second] = 1;
                    }
                }
            }
        }
    }

    struct Action {
        std::vector<std::uint32_t> pre, add;
    };

    const std::vector<Action>& actions() const { return actions_; }

    const std::vector<std::vector<std::uint32_t>>& pre_of() const { return pre_of_; }

private:
    struct Template {
        std::vector<ObId> slot_obs; // the object of each entity slot (L's entity parts)
        std::vector<Fact> pre, add; // add: R's facts that are not already L's
    };

    std::uint32_t num_types() const {
        const auto& s = *schema_;
        return static_cast<std::uint32_t>(s.num_obs() + s.num_homs() + s.num_attrs());
    }

    // Decides which parts are entities (entities.hpp); those of objects that are not entity
    // objects are followed by name.
    void classify(const Problem& problem) {
        const auto& s = *schema_;
        const ACSet& init = *problem.initial;
        auto e = find_entities(*problem.domain, init);
        entity_ = e.whole;
        entity_parts_ = std::move(e.parts);
        by_name_.assign(s.num_obs(), {});
        has_entities_.assign(s.num_obs(), false);
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            has_entities_[o] = entity_[o] || !entity_parts_[o].empty();
            if (!entity_[o]) {
                for (Part p : entity_parts_[o]) {
                    by_name_[o].emplace(std::string(init.part_name(ObId(o), p)), p);
                }
            }
        }
    }

    // The entity a part of state x stands for (its initial part id), or nullopt for a fact part.
    std::optional<Part> state_entity(const ACSet& x, ObId ob, Part p) const {
        if (entity_[ob.index()]) {
            return p;
        }
        const auto& names = by_name_[ob.index()];
        if (names.empty()) {
            return std::nullopt;
        }
        auto it = names.find(x.part_name(ob, p));
        if (it == names.end()) {
            return std::nullopt;
        }
        return it->second;
    }

    // The ways the goal's parts of objects with entities can stand for initial entities: the
    // monic morphisms from those parts (with their attributes and the homs between them) into
    // the initial state's entities, the goal's names bound to the initial state's. A goal may
    // leave entities interchangeable (two purple blocks); keeping every identification (up to
    // kMaxGoalMaps) and taking the least h over them keeps h at 0 in every goal state. With more
    // identifications than that, or none, the entities not fixed by name are wildcards.
    static constexpr std::uint64_t kMaxGoalMaps = 24;

    std::vector<std::vector<std::vector<Part>>> goal_entities(const ACSet& g,
                                                              const ACSet& init) const {
        const auto& s = *schema_;
        std::vector<std::vector<Part>> by_name(s.num_obs());
        ACSet only(g);
        hom::HomSearchOptions opt;
        opt.monic_all = true;
        opt.max_results = kMaxGoalMaps + 1;
        opt.accept = [&](ObId ob, Part, Part q) { return is_entity(ob, q); };
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            ObId ob(o);
            by_name[o].assign(g.num_parts(ob), kNoPart);
            if (!has_entities_[o]) {
                for (Part p = static_cast<Part>(g.num_parts(ob)); p-- > 0;) {
                    only.remove_part(ob, p);
                }
                continue;
            }
            for (Part p = 0; p < g.num_parts(ob); ++p) {
                auto name = g.part_name(ob, p);
                auto q = name.empty() ? std::nullopt : init.find_part(ob, name);
                if (q && is_entity(ob, *q)) {
                    by_name[o][p] = *q;
                    opt.bind(ob, p, *q);
                }
            }
        }
        auto ms = hom::find_homomorphisms(only, init, opt).morphisms;
        if (ms.empty() || ms.size() > kMaxGoalMaps) {
            return {by_name};
        }
        std::vector<std::vector<std::vector<Part>>> images;
        for (const auto& m : ms) {
            auto image = by_name;
            for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
                if (has_entities_[o]) {
                    image[o] = m.components[o];
                }
            }
            images.push_back(std::move(image));
        }
        return images;
    }

    bool is_entity(ObId ob, Part initial_part) const {
        const auto& ps = entity_parts_[ob.index()];
        return std::binary_search(ps.begin(), ps.end(), initial_part);
    }

    // The facts of a state or pattern. `entity` says what a part of an object with entities
    // stands for: a position (a slot, an initial entity, a wildcard), or nullopt for a fact part.
    using EntityOf = std::function<std::optional<Pos>(ObId, Part)>;

    std::vector<Fact> facts_of(const ACSet& a, const EntityOf& entity) const {
        const auto& s = *schema_;
        std::vector<Fact> facts;
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            ObId ob(o);
            for (Part p = 0; p < a.num_parts(ob); ++p) {
                auto e = has_entities_[o] ? entity(ob, p) : std::nullopt;
                if (e) {
                    entity_facts(a, ob, p, *e, entity, facts);
                } else {
                    facts.push_back(part_fact(a, ob, p, entity));
                }
            }
        }
        return facts;
    }

    static Pos value_pos(const Value& v) {
        return v.is_concrete() ? Pos{Pos::Kind::Const, v.hash()} : Pos{};
    }

    // A fact part (a predicate object's part): its hom values into objects with entities (a
    // wildcard where the target is not an entity) and its attribute values.
    Fact part_fact(const ACSet& a, ObId ob, Part p, const EntityOf& entity) const {
        const auto& s = *schema_;
        Fact f{ob.index(), {}};
        for (HomId h : s.homs_from(ob)) {
            ObId cod = s.hom(h).codom;
            if (!has_entities_[cod.index()]) {
                continue;
            }
            Part q = a.subpart(h, p);
            auto e = q == kNoPart ? std::nullopt : entity(cod, q);
            f.pos.push_back(e ? *e : Pos{});
        }
        for (AttrId at : s.attrs_from(ob)) {
            f.pos.push_back(value_pos(a.subpart(at, p)));
        }
        return f;
    }

    // An entity part's facts: its hom values into entities and its concrete attribute values.
    void entity_facts(const ACSet& a, ObId ob, Part p, Pos self, const EntityOf& entity,
                      std::vector<Fact>& facts) const {
        const auto& s = *schema_;
        for (HomId h : s.homs_from(ob)) {
            ObId cod = s.hom(h).codom;
            Part q = a.subpart(h, p);
            auto e = q == kNoPart || !has_entities_[cod.index()] ? std::nullopt : entity(cod, q);
            if (e) {
                facts.push_back({static_cast<std::uint32_t>(s.num_obs() + h.index()), {self, *e}});
            }
        }
        for (AttrId at : s.attrs_from(ob)) {
            const Value& v = a.subpart(at, p);
            if (v.is_concrete()) {
                facts.push_back(
                    {static_cast<std::uint32_t>(s.num_obs() + s.num_homs() + at.index()),
                     {self, value_pos(v)}});
            }
        }
    }

    std::vector<Fact> state_facts(const ACSet& x) const {
        return facts_of(x, [&](ObId ob, Part p) -> std::optional<Pos> {
            auto e = state_entity(x, ob, p);
            return e ? std::optional<Pos>(Pos{Pos::Kind::Const, *e}) : std::nullopt;
        });
    }

    // A rule's slots are its kept L parts of objects with entities; its deleted L parts and
    // created R parts are fact parts.
    Template make_template(const Rule& rule) const {
        const auto& s = *schema_;
        Template t;
        std::vector<std::vector<std::uint64_t>> slot(s.num_obs());
        std::vector<std::vector<std::uint64_t>> r_slot(s.num_obs());
        constexpr auto kNone = std::numeric_limits<std::uint64_t>::max();
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            ObId ob(o);
            slot[o].assign(rule.L.num_parts(ob), kNone);
            r_slot[o].assign(rule.R.num_parts(ob), kNone);
            if (!has_entities_[o]) {
                continue;
            }
            for (Part k = 0; k < rule.K.num_parts(ob); ++k) {
                slot[o][rule.l(ob, k)] = t.slot_obs.size();
                r_slot[o][rule.r(ob, k)] = t.slot_obs.size();
                t.slot_obs.push_back(ob);
            }
        }
        auto by = [](const std::vector<std::vector<std::uint64_t>>& slots) {
            return [&slots](ObId ob, Part p) -> std::optional<Pos> {
                std::uint64_t v = slots[ob.index()][p];
                return v == kNone ? std::nullopt : std::optional<Pos>(Pos{Pos::Kind::Slot, v});
            };
        };
        t.pre = facts_of(rule.L, by(slot));
        for (auto& f : facts_of(rule.R, by(r_slot))) {
            if (std::find(t.pre.begin(), t.pre.end(), f) == t.pre.end()) {
                t.add.push_back(std::move(f));
            }
        }
        return t;
    }

    void add_mask(const Fact& f) {
        auto& ms = masks_[f.type];
        std::uint64_t m = mask_of(f);
        if (std::find(ms.begin(), ms.end(), m) == ms.end()) {
            ms.push_back(m);
        }
    }

    std::uint32_t prop(std::uint64_t key) {
        auto [it, inserted] = props_.try_emplace(key, static_cast<std::uint32_t>(num_props_));
        if (inserted) {
            ++num_props_;
        }
        return it->second;
    }

    static std::vector<Pos> instantiate(const Fact& f, const std::vector<Part>& assignment) {
        std::vector<Pos> pos = f.pos;
        for (auto& p : pos) {
            if (p.kind == Pos::Kind::Slot) {
                p = Pos{Pos::Kind::Const, assignment[p.value]};
            }
        }
        return pos;
    }

    // Every injective assignment of each rule's entity slots to the initial state's entities
    // whose static preconditions hold initially; then the adds, once every needed prop exists.
    void ground() {
        struct Pending {
            std::size_t rule;
            std::vector<Part> assignment;
        };

        std::vector<Pending> pending;
        for (std::size_t ri = 0; ri < templates_.size(); ++ri) {
            const auto& t = templates_[ri];
            // The static preconditions checkable once slot i is assigned (their last slot).
            std::vector<std::vector<const Fact*>> checks(t.slot_obs.size() + 1);
            for (const auto& f : t.pre) {
                if (dynamic_[f.type]) {
                    continue;
                }
                std::size_t last = 0;
                for (const auto& p : f.pos) {
                    if (p.kind == Pos::Kind::Slot) {
                        last = std::max<std::size_t>(last, p.value + 1);
                    }
                }
                checks[last].push_back(&f);
            }
            auto holds = [&](std::size_t level, const std::vector<Part>& a) {
                for (const Fact* f : checks[level]) {
                    if (!initial_static_.contains(
                            key_of(f->type, mask_of(*f), instantiate(*f, a)))) {
                        return false;
                    }
                }
                return true;
            };
            std::vector<Part> a(t.slot_obs.size(), kNoPart);
            std::function<void(std::size_t)> assign = [&](std::size_t i) {
                if (budget_ != nullptr) {
                    budget_->poll();
                }
                if (i == a.size()) {
                    pending.push_back({ri, a});
                    return;
                }
                for (Part p : entity_parts_[t.slot_obs[i].index()]) {
                    bool used = false;
                    for (std::size_t j = 0; j < i; ++j) {
                        used = used || (t.slot_obs[j] == t.slot_obs[i] && a[j] == p);
                    }
                    if (used) {
                        continue;
                    }
                    a[i] = p;
                    if (holds(i + 1, a)) {
                        assign(i + 1);
                    }
                }
                a[i] = kNoPart;
            };
            if (holds(0, a)) {
                assign(0);
            }
        }
        for (const auto& pa : pending) {
            if (budget_ != nullptr) {
                budget_->poll();
            }
            Action act;
            for (const auto& f : templates_[pa.rule].pre) {
                if (dynamic_[f.type]) {
                    act.pre.push_back(
                        prop(key_of(f.type, mask_of(f), instantiate(f, pa.assignment))));
                }
            }
            std::sort(act.pre.begin(), act.pre.end());
            act.pre.erase(std::unique(act.pre.begin(), act.pre.end()), act.pre.end());
            actions_.push_back(std::move(act));
        }
        for (std::size_t i = 0; i < pending.size(); ++i) {
            auto& act = actions_[i];
            for (const auto& f : templates_[pending[i].rule].add) {
                auto pos = instantiate(f, pending[i].assignment);
                Fact g{f.type, pos};
                std::uint64_t fm = mask_of(g);
                for (std::uint64_t m : masks_[f.type]) {
                    if ((fm & m) == m) {
                        auto it = props_.find(key_of(f.type, m, pos));
                        if (it != props_.end()) {
                            act.add.push_back(it->second);
                        }
                    }
                }
            }
            std::sort(act.add.begin(), act.add.end());
            act.add.erase(std::unique(act.add.begin(), act.add.end()), act.add.end());
        }
        pre_of_.assign(num_props_, {});
        for (std::uint32_t a = 0; a < actions_.size(); ++a) {
            for (std::uint32_t p : actions_[a].pre) {
                pre_of_[p].push_back(a);
            }
        }
    }

    schema::SchemaPtr schema_;
    Budget* budget_;
    std::vector<bool> entity_;       // per ob: every part is an entity (none created or deleted)
    std::vector<bool> has_entities_; // per ob: some initial part is an entity
    std::vector<std::vector<Part>> entity_parts_; // per ob: the initial entities, sorted
    std::vector<std::map<std::string, Part, std::less<>>> by_name_; // per ob not entity_: by name
    std::vector<Template> templates_;
    std::vector<std::vector<std::uint64_t>> masks_;
    std::vector<bool> dynamic_;
    std::unordered_set<std::uint64_t> initial_static_;
    std::unordered_map<std::uint64_t, std::uint32_t> props_;
    std::size_t num_props_ = 0;
    std::vector<std::vector<std::uint32_t>> goals_;
    std::vector<Action> actions_;
    std::vector<std::vector<std::uint32_t>> pre_of_;
};

class Blind final : public Heuristic {
public:
    int evaluate(const ACSet&) override { return 0; }
};

class GoalCount final : public Heuristic {
public:
    GoalCount(const Problem& p, Budget* budget) : task_(p, budget) {}

    int evaluate(const ACSet& x) override {
        task_.props_of(x, truth_);
        int best = kDeadEnd;
        for (const auto& goal : task_.goals()) {
            int h = 0;
            for (auto g : goal) {
                h += truth_[g] ? 0 : 1;
            }
            best = std::min(best, h);
        }
        return best;
    }

private:
    RelaxedTask task_;
    std::vector<char> truth_;
};

// h_add by a generalised Dijkstra over props; h_FF marks the best supporters' relaxed plan.
class Additive final : public Heuristic {
public:
    enum class Mode { Add, Max, FF };

    Additive(const Problem& p, Mode mode, Budget* budget) : task_(p, budget), mode_(mode) {}

    int evaluate(const ACSet& x) override {
        constexpr int kInf = std::numeric_limits<int>::max();
        const auto& actions = task_.actions();
        task_.props_of(x, truth_);
        cost_.assign(task_.num_props(), kInf);
        supporter_.assign(task_.num_props(), UINT32_MAX);
        unsat_.resize(actions.size());
        sum_.assign(actions.size(), 0);
        // A binary heap in a member vector, so evaluations reuse its storage.
        auto& queue = queue_;
        queue.clear();
        auto push = [&](int c, std::uint32_t p) {
            queue.push_back({c, p});
            std::push_heap(queue.begin(), queue.end(), std::greater<>());
        };
        for (std::uint32_t p = 0; p < truth_.size(); ++p) {
            if (truth_[p]) {
                cost_[p] = 0;
                push(0, p);
            }
        }
        auto fire = [&](std::uint32_t a) {
            int c = 1 + sum_[a]; // sum_ holds the largest precondition cost for h_max
            for (std::uint32_t q : actions[a].add) {
                if (c < cost_[q]) {
                    cost_[q] = c;
                    supporter_[q] = a;
                    push(c, q);
                }
            }
        };
        for (std::uint32_t a = 0; a < actions.size(); ++a) {
            unsat_[a] = static_cast<std::uint32_t>(actions[a].pre.size());
            if (unsat_[a] == 0) {
                fire(a);
            }
        }
        while (!queue.empty()) {
            task_.poll();
            std::pop_heap(queue.begin(), queue.end(), std::greater<>());
            auto [c, p] = queue.back();
            queue.pop_back();
            if (c > cost_[p]) {
                continue;
            }
            for (std::uint32_t a : task_.pre_of()[p]) {
                sum_[a] =
                    mode_ == Mode::Max ? std::max(sum_[a], c) : std::min(sum_[a] + c, kDeadEnd);
                if (--unsat_[a] == 0) {
                    fire(a);
                }
            }
        }
        int best = kDeadEnd;
        for (const auto& goal : task_.goals()) {
            best =
                std::min(best, mode_ == Mode::FF ? relaxed_plan_size(goal) : additive_cost(goal));
        }
        return best;
    }

private:
    int additive_cost(const std::vector<std::uint32_t>& goal) const {
        constexpr int kInf = std::numeric_limits<int>::max();
        long total = 0;
        for (auto g : goal) {
            if (cost_[g] == kInf) {
                return kDeadEnd;
            }
            total = mode_ == Mode::Max ? std::max<long>(total, cost_[g]) : total + cost_[g];
        }
        return static_cast<int>(std::min<long>(total, kDeadEnd - 1));
    }

    // The relaxed plan: the best supporter of each goal prop, then of their preconditions.
    int relaxed_plan_size(const std::vector<std::uint32_t>& goal) {
        constexpr int kInf = std::numeric_limits<int>::max();
        const auto& actions = task_.actions();
        for (auto g : goal) {
            if (cost_[g] == kInf) {
                return kDeadEnd;
            }
        }
        in_plan_.assign(actions.size(), false);
        std::vector<std::uint32_t> stack(goal.begin(), goal.end());
        marked_.assign(task_.num_props(), false);
        int count = 0;
        while (!stack.empty()) {
            std::uint32_t p = stack.back();
            stack.pop_back();
            if (marked_[p] || cost_[p] == 0) {
                continue;
            }
            marked_[p] = true;
            std::uint32_t a = supporter_[p];
            if (!in_plan_[a]) {
                in_plan_[a] = true;
                ++count;
                stack.insert(stack.end(), actions[a].pre.begin(), actions[a].pre.end());
            }
        }
        return count;
    }

    RelaxedTask task_;
    Mode mode_;
    std::vector<char> truth_;
    std::vector<int> cost_, sum_;
    std::vector<std::uint32_t> supporter_, unsat_;
    std::vector<bool> in_plan_, marked_;
    std::vector<std::pair<int, std::uint32_t>> queue_;
};

} // namespace

std::unique_ptr<Heuristic> make_heuristic(HeuristicKind kind, const Problem& problem,
                                          Budget* budget) {
    switch (kind) {
    case HeuristicKind::Blind:
        return std::make_unique<Blind>();
    case HeuristicKind::GoalCount:
        return std::make_unique<GoalCount>(problem, budget);
    case HeuristicKind::HAdd:
        return std::make_unique<Additive>(problem, Additive::Mode::Add, budget);
    case HeuristicKind::HMax:
    case HeuristicKind::LmCut:
        return std::make_unique<Additive>(problem, Additive::Mode::Max, budget);
    case HeuristicKind::Default:
    case HeuristicKind::HFF:
    case HeuristicKind::LmCount:
        return std::make_unique<Additive>(problem, Additive::Mode::FF, budget);
    }
    CATPLAN_UNREACHABLE("heuristic kind");
}

} // namespace catplan::plan
