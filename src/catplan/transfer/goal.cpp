#include "catplan/transfer/goal.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/transfer/terms.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <queue>
#include <tuple>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using acset::Value;

struct Statement {
    enum class Kind : std::uint8_t { Part, Hom, Attr };
    Kind kind = Kind::Part;
    std::size_t part = 0;  // index into the goal's part list
    std::size_t other = 0; // Hom: the index of f(part)
    HomId hom;
    AttrId attr;
    Value value;
};

struct GoalPart {
    ObId ob;
    Part p = 0;
};

// The goal read as statements over an indexed list of its parts.
struct Goal {
    std::vector<GoalPart> parts;
    std::vector<std::vector<std::size_t>> index; // [ob][p] -> index in parts
    std::vector<Statement> statements;
};

Goal read_goal(const ACSet& g) {
    const auto& s = g.schema();
    Goal out;
    out.index.resize(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < g.num_parts(ObId(o)); ++p) {
            out.index[o].push_back(out.parts.size());
            out.parts.push_back({ObId(o), p});
        }
    }
    for (std::size_t i = 0; i < out.parts.size(); ++i) {
        auto [ob, p] = out.parts[i];
        Statement st;
        st.part = i;
        out.statements.push_back(st);
        for (HomId f : s.homs_from(ob)) {
            Part q = g.subpart(f, p);
            if (q == kNoPart) {
                continue;
            }
            Statement h;
            h.kind = Statement::Kind::Hom;
            h.part = i;
            h.hom = f;
            h.other = out.index[s.hom(f).codom.index()][q];
            out.statements.push_back(h);
        }
        for (AttrId a : s.attrs_from(ob)) {
            const Value& v = g.subpart(a, p);
            if (!v.is_concrete()) {
                continue;
            }
            Statement at;
            at.kind = Statement::Kind::Attr;
            at.part = i;
            at.attr = a;
            at.value = v;
            out.statements.push_back(at);
        }
    }
    return out;
}

// A statement in words (made only where it is printed: a goal of a large state has many).
std::string text(const ACSet& g, const Goal& goal, const Statement& st) {
    auto [ob, p] = goal.parts[st.part];
    switch (st.kind) {
    case Statement::Kind::Part:
        return part_statement(g, ob, p);
    case Statement::Kind::Hom:
        return hom_statement(g, st.hom, p);
    case Statement::Kind::Attr:
        return attr_statement(g, st.attr, p);
    }
    CATPLAN_UNREACHABLE("statement kind");
}

// Branch and bound over the goal's parts in a fixed order; each statement is decided when the
// later of its parts is.
class Search {
public:
    Search(const Goal& goal, const ACSet& x, std::uint64_t node_limit)
        : goal_(goal), x_(x), node_limit_(node_limit) {
        order_parts();
        attach_statements();
        assign_.assign(goal_.parts.size(), kNoPart);
        used_.resize(x.schema().num_obs());
        for (std::uint32_t o = 0; o < x.schema().num_obs(); ++o) {
            used_[o].assign(x.num_parts(ObId(o)), false);
        }
        best_assign_ = assign_;
    }

    void run() {
        if (!goal_.statements.empty()) {
            step(0, 0);
        }
    }

    std::size_t best() const { return best_; }

    bool exact() const { return exact_; }

    // Whether statement i holds under the best assignment.
    bool holds(const Statement& st) const { return satisfied(st, best_assign_); }

private:
    static constexpr std::size_t kMaxCandidates = 64;

    void order_parts() {
        // Each next part is the one with the most hom statements linking it to the parts placed
        // already (then the most statements), so that hom statements are decided early and
        // prune, and a part reached by a hom finds its candidate at once.
        const std::size_t n = goal_.parts.size();
        std::vector<std::size_t> weight(n, 0), links(n, 0);
        std::vector<std::vector<std::size_t>> neighbours(n);
        for (const auto& st : goal_.statements) {
            ++weight[st.part];
            if (st.kind == Statement::Kind::Hom) {
                ++weight[st.other];
                neighbours[st.part].push_back(st.other);
                neighbours[st.other].push_back(st.part);
            }
        }
        using Entry = std::tuple<std::size_t, std::size_t, std::size_t>; // links, weight, n - i
        std::priority_queue<Entry> queue;
        for (std::size_t i = 0; i < n; ++i) {
            queue.emplace(0, weight[i], n - i);
        }
        std::vector<bool> placed(n, false);
        order_.clear();
        while (!queue.empty()) {
            auto [l, w, r] = queue.top();
            queue.pop();
            std::size_t i = n - r;
            if (placed[i] || l != links[i]) {
                continue; // placed, or a stale entry
            }
            placed[i] = true;
            order_.push_back(i);
            for (std::size_t j : neighbours[i]) {
                if (!placed[j]) {
                    queue.emplace(++links[j], weight[j], n - j);
                }
            }
        }
        position_.assign(n, 0);
        for (std::size_t k = 0; k < order_.size(); ++k) {
            position_[order_[k]] = k;
        }
    }

    void attach_statements() {
        at_.resize(order_.size());
        for (std::size_t i = 0; i < goal_.statements.size(); ++i) {
            const auto& st = goal_.statements[i];
            std::size_t k = position_[st.part];
            if (st.kind == Statement::Kind::Hom) {
                k = std::max(k, position_[st.other]);
            }
            at_[k].push_back(i);
        }
        remaining_.assign(order_.size() + 1, 0);
        for (std::size_t k = order_.size(); k-- > 0;) {
            remaining_[k] = remaining_[k + 1] + at_[k].size();
        }
    }

    bool satisfied(const Statement& st, const std::vector<Part>& a) const {
        Part p = a[st.part];
        if (p == kNoPart) {
            return false;
        }
        switch (st.kind) {
        case Statement::Kind::Part:
            return true;
        case Statement::Kind::Hom:
            return a[st.other] != kNoPart && x_.subpart(st.hom, p) == a[st.other];
        case Statement::Kind::Attr:
            return x_.subpart(st.attr, p) == st.value;
        }
        return false;
    }

    std::size_t gain(std::size_t k) const {
        std::size_t g = 0;
        for (std::size_t i : at_[k]) {
            g += satisfied(goal_.statements[i], assign_) ? 1 : 0;
        }
        return g;
    }

    void step(std::size_t k, std::size_t score) {
        if (have_best_ && (best_ == goal_.statements.size() || score + remaining_[k] <= best_)) {
            return;
        }
        if (node_limit_ != 0 && ++nodes_ > node_limit_) {
            exact_ = false;
            return;
        }
        if (k == order_.size()) {
            if (!have_best_ || score > best_) {
                have_best_ = true;
                best_ = score;
                best_assign_ = assign_;
            }
            return;
        }
        const GoalPart& gp = goal_.parts[order_[k]];
        auto& used = used_[gp.ob.index()];
        // Candidates with their gains, best first; "unassigned" is tried last.
        std::vector<std::pair<std::size_t, Part>> cands;
        for (Part c = 0; c < used.size(); ++c) {
            if (!used[c]) {
                assign_[order_[k]] = c;
                cands.emplace_back(gain(k), c);
            }
        }
        assign_[order_[k]] = kNoPart;
        std::stable_sort(cands.begin(), cands.end(),
                         [](const auto& a, const auto& b) { return a.first > b.first; });
        if (cands.size() > kMaxCandidates) {
            cands.resize(kMaxCandidates);
            exact_ = false;
        }
        for (auto [g, c] : cands) {
            assign_[order_[k]] = c;
            used[c] = true;
            step(k + 1, score + g);
            used[c] = false;
        }
        assign_[order_[k]] = kNoPart;
        step(k + 1, score + gain(k));
    }

    const Goal& goal_;
    const ACSet& x_;
    std::uint64_t node_limit_;
    std::uint64_t nodes_ = 0;
    std::vector<std::size_t> order_, position_;
    std::vector<std::vector<std::size_t>> at_;
    std::vector<std::size_t> remaining_;
    std::vector<Part> assign_, best_assign_;
    std::vector<std::vector<bool>> used_;
    std::size_t best_ = 0;
    bool have_best_ = false;
    bool exact_ = true;
};

} // namespace

std::vector<std::string> goal_statements(const ACSet& goal) {
    std::vector<std::string> out;
    Goal g = read_goal(goal);
    for (const auto& st : g.statements) {
        out.push_back(text(goal, g, st));
    }
    return out;
}

std::size_t count_goal_statements(const ACSet& goal) {
    return read_goal(goal).statements.size();
}

GoalSatisfaction goal_satisfaction(const ACSet& goal, const ACSet& x, std::uint64_t node_limit) {
    CATPLAN_ASSERT(&goal.schema() == &x.schema(), "goal and state on different schemas");
    Goal g = read_goal(goal);
    if (plan::embed_goal(goal, x)) {
        return {g.statements.size(), g.statements.size(), {}, true}; // a monic G -> X: all hold
    }
    Search search(g, x, node_limit);
    search.run();
    GoalSatisfaction out;
    out.total = g.statements.size();
    out.satisfied = search.best();
    out.exact = search.exact();
    for (const auto& st : g.statements) {
        if (!search.holds(st)) {
            out.unsatisfied.push_back(text(goal, g, st));
        }
    }
    return out;
}

} // namespace catplan::transfer
