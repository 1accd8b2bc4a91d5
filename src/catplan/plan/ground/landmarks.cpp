#include "catplan/plan/ground/landmarks.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <set>

namespace catplan::plan::ground {

namespace {

constexpr std::size_t kMaxLandmarks = 20'000;
constexpr std::size_t kMaxDisjunction = 4;

class Finder {
public:
    Finder(const Task& task, const RelaxedTask& r, Budget& budget)
        : task_(task), r_(r), budget_(budget) {
        init_.assign(r.num_props(), 0);
        for (VarId v = 0; v < task.vars.size(); ++v) {
            init_[r.prop(v, task.initial[v])] = 1;
        }
    }

    std::vector<Landmark> run() {
        // The goal: its facts when it is one term; else, through the goal proposition, what the
        // terms share (back-chained like any landmark, but not a landmark itself).
        std::vector<Prop> goal = r_.goal();
        bool one_term = task_.goal.size() == 1;
        if (one_term) {
            for (Prop g : goal) {
                add({r_.fact(g)}, kNone, true);
            }
        } else if (!goal.empty()) {
            back_chain({goal[0]}, kNone, true);
        }
        while (!queue_.empty()) {
            budget_.poll();
            std::uint32_t id = queue_.front();
            queue_.pop_front();
            std::vector<Prop> props;
            for (const Fact& f : lms_[id].facts) {
                props.push_back(r_.prop(f));
            }
            back_chain(props, id, false);
        }
        for (auto& lm : lms_) {
            for (const Fact& f : lm.facts) {
                auto ach = r_.achievers(r_.prop(f));
                lm.achievers.insert(lm.achievers.end(), ach.begin(), ach.end());
            }
            std::sort(lm.achievers.begin(), lm.achievers.end());
            lm.achievers.erase(std::unique(lm.achievers.begin(), lm.achievers.end()),
                               lm.achievers.end());
        }
        return std::move(lms_);
    }

private:
    // The landmark with these facts (added when new); ordered before `child` unless kNone.
    void add(std::vector<Fact> facts, std::uint32_t child, bool goal) {
        std::sort(facts.begin(), facts.end());
        auto it = index_.find(facts);
        std::uint32_t id;
        if (it == index_.end()) {
            if (lms_.size() >= kMaxLandmarks) {
                return;
            }
            id = static_cast<std::uint32_t>(lms_.size());
            lms_.push_back({facts, {}, {}, goal, {}});
            index_.emplace(facts, id);
            bool initially = std::any_of(facts.begin(), facts.end(),
                                         [&](const Fact& f) { return init_[r_.prop(f)] != 0; });
            if (!initially) {
                queue_.push_back(id);
            }
        } else {
            id = it->second;
            lms_[id].goal = lms_[id].goal || goal;
        }
        if (child != kNone && child != id) {
            auto& ps = lms_[child].parents;
            if (std::find(ps.begin(), ps.end(), id) == ps.end()) {
                ps.push_back(id);
                lms_[id].children.push_back(child);
            }
        }
    }

    // The propositions reachable in the relaxation without the actions that add one of `props`.
    void reachable_without(const std::vector<Prop>& props) {
        reached_.assign(r_.num_props(), 0);
        banned_.assign(r_.num_actions(), 0);
        for (Prop p : props) {
            for (std::uint32_t a : r_.achievers(p)) {
                banned_[a] = 1;
            }
        }
        unsat_.assign(r_.num_pres().begin(), r_.num_pres().end());
        std::vector<Prop> stack;
        auto reach = [&](Prop p) {
            if (!reached_[p]) {
                reached_[p] = 1;
                stack.push_back(p);
            }
        };
        for (Prop p = 0; p < r_.num_props(); ++p) {
            if (init_[p]) {
                reach(p);
            }
        }
        for (std::uint32_t a : r_.unconditional()) {
            if (!banned_[a]) {
                for (Prop q : r_.add(a)) {
                    reach(q);
                }
            }
        }
        while (!stack.empty()) {
            Prop p = stack.back();
            stack.pop_back();
            for (std::uint32_t a : r_.pre_of(p)) {
                if (--unsat_[a] == 0 && !banned_[a]) {
                    for (Prop q : r_.add(a)) {
                        reach(q);
                    }
                }
            }
        }
    }

    // Shared preconditions of the possible first achievers of `props` become landmarks before
    // `child` (kNone: the goal proposition), and so do variables they all need.
    void back_chain(const std::vector<Prop>& props, std::uint32_t child, bool goal) {
        reachable_without(props);
        std::vector<std::uint32_t> first;
        for (Prop p : props) {
            for (std::uint32_t a : r_.achievers(p)) {
                auto pre = r_.pre(a);
                if (std::all_of(pre.begin(), pre.end(), [&](Prop q) { return reached_[q] != 0; })) {
                    first.push_back(a);
                }
            }
        }
        if (first.empty()) {
            return;
        }
        std::sort(first.begin(), first.end());
        first.erase(std::unique(first.begin(), first.end()), first.end());
        // Per variable: the values the first achievers need, and how many need it at all.
        std::map<VarId, std::pair<std::size_t, std::vector<std::uint32_t>>> need;
        for (std::uint32_t a : first) {
            for (Prop q : r_.pre(a)) {
                Fact f = r_.fact(q);
                if (f.var == kNone) {
                    continue;
                }
                auto& [count, values] = need[f.var];
                ++count;
                if (std::find(values.begin(), values.end(), f.value) == values.end()) {
                    values.push_back(f.value);
                }
            }
        }
        for (auto& [var, entry] : need) {
            auto& [count, values] = entry;
            if (count < first.size()) {
                continue; // some first achiever does not need this variable
            }
            if (values.size() == 1) {
                add({{var, values[0]}}, child, goal && child == kNone);
            } else if (values.size() <= kMaxDisjunction) {
                std::vector<Fact> facts;
                for (auto v : values) {
                    facts.push_back({var, v});
                }
                add_disjunction(std::move(facts), child);
            }
        }
        predicate_disjunctions(first, child);
    }

    // A disjunctive landmark before `child`, unless one of its facts holds initially or is in
    // another disjunctive landmark (Fast Downward's RHW keeps the first of overlapping ones).
    void add_disjunction(std::vector<Fact> facts, std::uint32_t child) {
        for (const Fact& f : facts) {
            if (init_[r_.prop(f)] != 0) {
                return;
            }
        }
        std::sort(facts.begin(), facts.end());
        if (index_.find(facts) == index_.end()) {
            for (const Fact& f : facts) {
                if (in_disjunction_.count(f) > 0) {
                    return;
                }
            }
            in_disjunction_.insert(facts.begin(), facts.end());
        }
        add(std::move(facts), child, false);
    }

    // As RHW's disjunction classes: facts of atoms of one predicate (an object of the schema),
    // one a precondition of each first achiever, are a disjunctive landmark when there are at
    // most kMaxDisjunction of them. In a gripper domain, every first achiever of (at b roomb)
    // needs (carry b left) or (carry b right): atoms of one predicate, on two variables, which
    // the variables' own disjunctions above cannot see. Facts that are landmarks alone are left
    // out of the classes.
    void predicate_disjunctions(const std::vector<std::uint32_t>& first, std::uint32_t child) {
        struct Class {
            std::size_t users = 0; // first achievers with a precondition in the class
            std::size_t last = SIZE_MAX;
            std::vector<Fact> facts;
        };

        std::map<std::uint32_t, Class> classes; // by the atoms' object
        for (std::size_t i = 0; i < first.size(); ++i) {
            for (Prop q : r_.pre(first[i])) {
                Fact f = r_.fact(q);
                if (f.var == kNone || f.value != 1 ||
                    task_.vars[f.var].kind != Variable::Kind::Atom ||
                    index_.count(std::vector<Fact>{f}) > 0) {
                    continue;
                }
                auto& c = classes[task_.atoms[task_.vars[f.var].owner].ob.index()];
                if (c.last != i) {
                    c.last = i;
                    ++c.users;
                }
                if (std::find(c.facts.begin(), c.facts.end(), f) == c.facts.end()) {
                    c.facts.push_back(f);
                }
            }
        }
        for (auto& [ob, c] : classes) {
            if (c.users == first.size() && c.facts.size() > 1 &&
                c.facts.size() <= kMaxDisjunction) {
                add_disjunction(std::move(c.facts), child);
            }
        }
    }

    const Task& task_;
    const RelaxedTask& r_;
    Budget& budget_;
    std::vector<char> init_, reached_, banned_;
    std::vector<std::uint32_t> unsat_;
    std::vector<Landmark> lms_;
    std::map<std::vector<Fact>, std::uint32_t> index_;
    std::set<Fact> in_disjunction_; // the facts of the disjunctive landmarks
    std::deque<std::uint32_t> queue_;
};

// Bit sets of accepted landmarks, one per state id, in blocks that never move.
class AcceptedSets {
public:
    explicit AcceptedSets(std::size_t bits) : words_(std::max<std::size_t>(1, (bits + 63) / 64)) {}

    std::uint64_t* at(StateId id) {
        std::size_t block = id / kPerBlock;
        while (block >= blocks_.size()) {
            blocks_.push_back(std::make_unique<std::uint64_t[]>(kPerBlock * words_));
        }
        return blocks_[block].get() + (id % kPerBlock) * words_;
    }

    std::size_t words() const { return words_; }

private:
    static constexpr std::size_t kPerBlock = 4096;
    std::size_t words_;
    std::vector<std::unique_ptr<std::uint64_t[]>> blocks_;
};

class LandmarkCount final : public Evaluator {
public:
    LandmarkCount(const Task& task, const RelaxedTask& r, Budget& budget)
        : task_(task), r_(r), lms_(find_landmarks(task, r, budget)), accepted_(lms_.size()) {
        of_prop_.assign(r.num_props(), {});
        for (std::uint32_t i = 0; i < lms_.size(); ++i) {
            for (const Fact& f : lms_[i].facts) {
                of_prop_[r.prop(f)].push_back(i);
            }
        }
        scratch_.resize(accepted_.words());
    }

    bool path_dependent() const override { return true; }

    void reach(StateId parent, ActionId, StateId child, const std::vector<std::uint32_t>& state,
               bool is_new) override {
        std::size_t w = accepted_.words();
        std::fill(scratch_.begin(), scratch_.end(), 0);
        const std::uint64_t* from = parent == kNone ? nullptr : accepted_.at(parent);
        if (from != nullptr) {
            std::copy(from, from + w, scratch_.begin());
        }
        for (std::uint32_t i = 0; i < lms_.size(); ++i) {
            if (test(scratch_.data(), i) || !holds(i, state)) {
                continue;
            }
            const auto& ps = lms_[i].parents;
            if (from == nullptr ||
                std::all_of(ps.begin(), ps.end(), [&](std::uint32_t p) { return test(from, p); })) {
                scratch_[i / 64] |= std::uint64_t{1} << (i % 64);
            }
        }
        std::uint64_t* to = accepted_.at(child);
        for (std::size_t k = 0; k < w; ++k) {
            to[k] = is_new ? scratch_[k] : (to[k] & scratch_[k]);
        }
    }

    int evaluate(StateId id, const std::vector<std::uint32_t>& state,
                 const std::vector<ActionId>* applicable,
                 std::vector<ActionId>* preferred) override {
        const std::uint64_t* acc = accepted_.at(id);
        interesting_.assign(lms_.size(), 0);
        int h = 0;
        for (std::uint32_t i = 0; i < lms_.size(); ++i) {
            bool needed = !test(acc, i);
            if (!needed && !holds(i, state)) {
                needed =
                    lms_[i].goal || std::any_of(lms_[i].children.begin(), lms_[i].children.end(),
                                                [&](std::uint32_t c) { return !test(acc, c); });
            }
            if (needed) {
                if (lms_[i].achievers.empty() && !holds(i, state)) {
                    return kDeadEnd;
                }
                interesting_[i] = 1;
                ++h;
            }
        }
        if (preferred != nullptr && h > 0) {
            prefer(state, applicable, *preferred);
        }
        return h;
    }

private:
    static bool test(const std::uint64_t* bits, std::uint32_t i) {
        return (bits[i / 64] >> (i % 64)) & 1;
    }

    bool holds(std::uint32_t i, const std::vector<std::uint32_t>& state) const {
        const auto& fs = lms_[i].facts;
        return std::any_of(fs.begin(), fs.end(),
                           [&](const Fact& f) { return state[f.var] == f.value; });
    }

    bool achieves_interesting(ActionId a) const {
        for (const Fact& f : task_.actions[a].eff) {
            for (std::uint32_t i : of_prop_[r_.prop(f)]) {
                if (interesting_[i]) {
                    return true;
                }
            }
        }
        return false;
    }

    // The applicable actions that achieve an interesting landmark.
    void prefer(const std::vector<std::uint32_t>& state, const std::vector<ActionId>* applicable,
                std::vector<ActionId>& out) const {
        if (applicable != nullptr) {
            for (ActionId a : *applicable) {
                if (task_.actions[a].exit.empty() && achieves_interesting(a)) {
                    out.push_back(a);
                }
            }
            return;
        }
        for (std::uint32_t i = 0; i < lms_.size(); ++i) {
            if (!interesting_[i]) {
                continue;
            }
            for (std::uint32_t ra : lms_[i].achievers) {
                if (r_.action(ra) == kNone) {
                    continue;
                }
                auto pre = r_.pre(ra);
                bool ok = std::all_of(pre.begin(), pre.end(), [&](Prop q) {
                    Fact f = r_.fact(q);
                    return f.var != kNone && state[f.var] == f.value;
                });
                if (ok) {
                    out.push_back(r_.action(ra));
                    out.insert(out.end(), r_.also(ra).begin(), r_.also(ra).end());
                }
            }
        }
    }

    const Task& task_;
    const RelaxedTask& r_;
    std::vector<Landmark> lms_;
    AcceptedSets accepted_;
    std::vector<std::vector<std::uint32_t>> of_prop_;
    std::vector<std::uint64_t> scratch_;
    std::vector<char> interesting_;
};

} // namespace

std::vector<Landmark> find_landmarks(const Task& task, const RelaxedTask& relaxed, Budget& budget) {
    return Finder(task, relaxed, budget).run();
}

std::unique_ptr<Evaluator> make_landmark_count(const Task& task, const RelaxedTask& relaxed,
                                               Budget& budget) {
    return std::make_unique<LandmarkCount>(task, relaxed, budget);
}

} // namespace catplan::plan::ground
