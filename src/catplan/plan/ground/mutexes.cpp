#include "catplan/plan/ground/mutexes.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <queue>
#include <set>

namespace catplan::plan::ground {

namespace {

// The hom positions of an atom's object that name its group, in the order of the parameters.
struct CandidatePart {
    std::uint32_t ob = 0;
    std::vector<std::uint32_t> positions;

    friend auto operator<=>(const CandidatePart&, const CandidatePart&) = default;
};

using Candidate = std::vector<CandidatePart>; // one part per object, sorted by object

using Key = std::vector<ObjectId>;

// Bounds on the analysis (a larger task gets fewer candidates checked, never a wrong group).
constexpr std::size_t kMaxCandidates = 1000;
constexpr std::size_t kMaxWork = 100'000'000; // atoms looked at, over all candidates

// Why a candidate fails on an action: it produces two atoms of one group (no refinement helps),
// or produces one of group `key` and consumes none.
struct Failure {
    bool too_heavy = false;
    ActionId action = kNone;
    Key key;
};

class Finder {
public:
    Finder(const Task& task, Budget& budget) : task_(task), budget_(budget) {
        produced_.resize(task.actions.size());
        consumed_.resize(task.actions.size());
        for (ActionId a = 0; a < task.actions.size(); ++a) {
            const Action& act = task.actions[a];
            if (!act.exit.empty()) {
                continue; // never applied
            }
            for (const Fact& e : act.eff) {
                if (task.vars[e.var].kind != Variable::Kind::Atom) {
                    continue;
                }
                auto pre =
                    std::lower_bound(act.pre.begin(), act.pre.end(), Fact{e.var, 0},
                                     [](const Fact& x, const Fact& y) { return x.var < y.var; });
                bool needed = pre != act.pre.end() && pre->var == e.var && pre->value == 1;
                AtomId atom = task.vars[e.var].owner;
                if (e.value == 1 && !needed) {
                    produced_[a].push_back(atom);
                } else if (e.value == 0 && needed) {
                    consumed_[a].push_back(atom);
                }
            }
        }
        atoms_of_.resize(task.problem->initial->schema().num_obs());
        for (AtomId i = 0; i < task.atoms.size(); ++i) {
            atoms_of_[task.atoms[i].ob.index()].push_back(i);
        }
    }

    std::vector<std::vector<VarId>> run() {
        for (std::uint32_t ob = 0; ob < atoms_of_.size(); ++ob) {
            if (atoms_of_[ob].empty()) {
                continue;
            }
            const Atom& a = task_.atoms[atoms_of_[ob].front()];
            auto k = static_cast<std::uint32_t>(a.homs.size());
            std::vector<std::uint32_t> all(k);
            for (std::uint32_t i = 0; i < k; ++i) {
                all[i] = i;
            }
            if (a.attrs.empty() || a.attrs.size() == 1) {
                enqueue({{ob, all}});
            }
            for (std::uint32_t free = 0; free < k && a.attrs.empty(); ++free) {
                auto some = all;
                some.erase(some.begin() + free);
                enqueue({{ob, some}});
            }
        }
        std::vector<std::vector<VarId>> groups;
        for (std::size_t n = 0; n < kMaxCandidates && work_ < kMaxWork && !queue_.empty(); ++n) {
            Candidate c = std::move(queue_.front());
            queue_.pop_front();
            budget_.poll();
            if (auto f = check(c)) {
                if (!f->too_heavy) {
                    refine(c, *f);
                }
                continue;
            }
            instantiate(c, groups);
        }
        std::sort(groups.begin(), groups.end());
        groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
        return groups;
    }

private:
    std::optional<std::size_t> part_index(const Candidate& c, std::uint32_t ob) const {
        for (std::size_t i = 0; i < c.size(); ++i) {
            if (c[i].ob == ob) {
                return i;
            }
        }
        return std::nullopt;
    }

    Key key_of(AtomId atom, const CandidatePart& part) const {
        Key key;
        for (std::uint32_t pos : part.positions) {
            key.push_back(task_.atoms[atom].homs[pos]);
        }
        return key;
    }

    // The group key of an atom under c, if its object has a part.
    std::optional<Key> group_of(const Candidate& c, AtomId atom) const {
        auto i = part_index(c, task_.atoms[atom].ob.index());
        if (!i) {
            return std::nullopt;
        }
        return key_of(atom, c[*i]);
    }

    // The first action that unbalances a group of c, or nullopt when c holds.
    std::optional<Failure> check(const Candidate& c) {
        std::vector<Key> made, used;
        for (ActionId a = 0; a < produced_.size(); ++a) {
            work_ += 1 + produced_[a].size() + consumed_[a].size();
            made.clear();
            for (AtomId atom : produced_[a]) {
                if (auto key = group_of(c, atom)) {
                    if (std::find(made.begin(), made.end(), *key) != made.end()) {
                        return Failure{true, a, *key};
                    }
                    made.push_back(std::move(*key));
                }
            }
            if (made.empty()) {
                continue;
            }
            used.clear();
            for (AtomId atom : consumed_[a]) {
                if (auto key = group_of(c, atom)) {
                    used.push_back(std::move(*key));
                }
            }
            for (const Key& key : made) {
                if (std::find(used.begin(), used.end(), key) == used.end()) {
                    return Failure{false, a, key};
                }
            }
        }
        return std::nullopt;
    }

    // New candidates: c with a part for an atom the failing action consumes, its parameters the
    // hom positions holding the group's key (at most one argument left free).
    void refine(const Candidate& c, const Failure& f) {
        for (AtomId atom : consumed_[f.action]) {
            const Atom& a = task_.atoms[atom];
            if (part_index(c, a.ob.index()) || a.homs.size() + a.attrs.size() > f.key.size() + 1) {
                continue;
            }
            std::vector<std::uint32_t> positions;
            extend(c, a, f.key, positions);
        }
    }

    void extend(const Candidate& c, const Atom& a, const Key& key,
                std::vector<std::uint32_t>& positions) {
        if (positions.size() == key.size()) {
            Candidate more = c;
            more.push_back({a.ob.index(), positions});
            std::sort(more.begin(), more.end());
            enqueue(std::move(more));
            return;
        }
        for (std::uint32_t pos = 0; pos < a.homs.size(); ++pos) {
            bool taken = std::find(positions.begin(), positions.end(), pos) != positions.end();
            if (!taken && a.homs[pos] == key[positions.size()]) {
                positions.push_back(pos);
                extend(c, a, key, positions);
                positions.pop_back();
            }
        }
    }

    // Adds c in its canonical form (parameters ordered as the first part's positions) unless
    // seen before.
    void enqueue(Candidate c) {
        std::vector<std::uint32_t> order(c.front().positions.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) {
            order[i] = i;
        }
        const auto& first = c.front().positions;
        std::sort(order.begin(), order.end(),
                  [&](std::uint32_t x, std::uint32_t y) { return first[x] < first[y]; });
        for (auto& part : c) {
            std::vector<std::uint32_t> permuted;
            for (std::uint32_t i : order) {
                permuted.push_back(part.positions[i]);
            }
            part.positions = std::move(permuted);
        }
        if (seen_.insert(c).second) {
            queue_.push_back(std::move(c));
        }
    }

    // The groups of a candidate that holds: those with at most one atom initially.
    void instantiate(const Candidate& c, std::vector<std::vector<VarId>>& groups) const {
        std::map<Key, std::vector<VarId>> by_key;
        for (const auto& part : c) {
            for (AtomId atom : atoms_of_[part.ob]) {
                by_key[key_of(atom, part)].push_back(task_.atoms[atom].var);
            }
        }
        for (auto& [key, vars] : by_key) {
            auto present = std::count_if(vars.begin(), vars.end(),
                                         [&](VarId v) { return task_.initial[v] == 1; });
            if (present <= 1 && vars.size() >= 2) {
                std::sort(vars.begin(), vars.end());
                groups.push_back(std::move(vars));
            }
        }
    }

    const Task& task_;
    Budget& budget_;
    std::vector<std::vector<AtomId>> produced_, consumed_; // per action
    std::vector<std::vector<AtomId>> atoms_of_;            // per object of the schema
    std::deque<Candidate> queue_;
    std::set<Candidate> seen_;
    std::size_t work_ = 0;
};

} // namespace

std::vector<std::vector<VarId>> find_mutex_groups(const Task& task, Budget& budget) {
    return Finder(task, budget).run();
}

std::vector<std::vector<VarId>> disjoint_groups(std::vector<std::vector<VarId>> groups) {
    std::set<VarId> covered;
    std::priority_queue<std::pair<std::size_t, std::size_t>> by_size;
    for (std::size_t i = 0; i < groups.size(); ++i) {
        by_size.emplace(groups[i].size(), i);
    }
    std::vector<std::vector<VarId>> out;
    while (!by_size.empty()) {
        auto [size, i] = by_size.top();
        by_size.pop();
        auto& g = groups[i];
        std::erase_if(g, [&](VarId v) { return covered.count(v) != 0; });
        if (g.size() < size) {
            if (g.size() >= 2) {
                by_size.emplace(g.size(), i); // smaller now: its turn comes again
            }
            continue;
        }
        covered.insert(g.begin(), g.end());
        out.push_back(std::move(g));
    }
    return out;
}

} // namespace catplan::plan::ground
