#include "catplan/transfer/focus.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/hom/hom_search.hpp"

#include <deque>
#include <fmt/format.h>
#include <numeric>
#include <span>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using acset::Value;

// A part of an object that homs point into: an entity or a created thing, known by its name.
bool pointed(const schema::Schema& s, ObId ob) {
    return !s.homs_into(ob).empty();
}

// Whether a subgoal's attribute value is satisfied by y's: an unknown or unset one by any value.
bool value_agrees(const Value& goal, const Value& y) {
    return !goal.is_concrete() || goal == y;
}

// The parts of x that keep says, as a state of their own: parts in their order, hom values,
// attribute values, names and every attribute variable of x.
ACSet induced(const ACSet& x, const std::vector<std::vector<char>>& keep) {
    const auto& s = x.schema();
    ACSet out(x.schema_ptr());
    std::vector<std::vector<Part>> to(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        to[o].assign(x.num_parts(ob), kNoPart);
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            if (keep[o][p]) {
                to[o][p] = out.add_part(ob, x.part_name(ob, p));
            }
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < x.num_vars(AttrTypeId(t)); ++j) {
            out.add_var(AttrTypeId(t), x.var_name(AttrTypeId(t), j));
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            Part q = to[o][p];
            if (q == kNoPart) {
                continue;
            }
            for (HomId f : s.homs_from(ob)) {
                Part t = x.subpart(f, p);
                if (t != kNoPart) {
                    Part tq = to[s.hom(f).codom.index()][t];
                    CATPLAN_ASSERT(tq != kNoPart, "a focus keeps what its parts point to");
                    out.set_subpart(f, q, tq);
                }
            }
            for (AttrId a : s.attrs_from(ob)) {
                out.set_subpart(a, q, x.subpart(a, p));
            }
        }
    }
    return out;
}

// Whether the subgoal's parts of ob are named as Y's first parts, in the same order, and no name
// of Y is shared: then each is its namesake. Δ_F(X_i) and Y_{i-1} list the objects they share so
// wherever no step created or deleted one (a blocks world's blocks), and a comparison of interned
// names costs far less than a look-up in the index of names.
bool names_in_order(const NamedState& y, const ACSet& goal, ObId ob) {
    auto yn = y.state().part_names(ob), gn = goal.part_names(ob);
    if (gn.size() != goal.num_parts(ob) || gn.size() > yn.size() || y.has_ambiguous_names(ob)) {
        return false;
    }
    for (std::size_t p = 0; p < gn.size(); ++p) {
        if (gn[p] == Symbol() || gn[p] != yn[p]) {
            return false;
        }
    }
    return true;
}

} // namespace

bool embeds_by_names(const NamedState& x, const ACSet& goal) {
    const auto& s = goal.schema();
    bool variables = false;
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        variables = variables || goal.num_vars(AttrTypeId(t)) > 0;
    }
    if (!variables) {
        // Part by part (a focus finds what differs by names), unless nothing differs and two
        // facts of the goal found the same fact of x.
        auto f = Focus::of(x, goal, Focus::Scan::FirstDifference);
        if (!f) {
            return false;
        }
        if (f->differs() || !f->shared_fact()) {
            return !f->differs();
        }
    }
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    opt.max_results = 1;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        if (!pointed(s, ob)) {
            continue;
        }
        for (Part p = 0; p < goal.num_parts(ob); ++p) {
            std::string_view name = goal.part_name(ob, p);
            Part q = name.empty() ? kNoPart : x.find(ob, name);
            if (q == kNoPart) {
                return false;
            }
            opt.bind(ob, p, q);
        }
    }
    return hom::is_homomorphic(goal, x.state(), opt);
}

Focus::Focus(const NamedState& y, const ACSet& subgoal) : y_(&y.state()), goal_(&subgoal) {}

Result<Focus> Focus::of(const NamedState& y, const ACSet& subgoal, Scan scan) {
    Focus f(y, subgoal);
    f.scan_ = scan;
    if (auto why = f.match_names(y)) {
        return fail(*why);
    }
    f.find_seeds();
    return f;
}

// Every part of the subgoal that homs point into has a namesake in Y.
std::optional<std::string> Focus::match_names(const NamedState& y) {
    const auto& s = y_->schema();
    std::size_t y_parts = 0, goal_parts = 0;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        y_parts += y_->num_parts(ObId(o));
        goal_parts += goal_->num_parts(ObId(o));
    }
    seeded_.reserve(s.num_obs(), y_parts);
    goal_part_.reserve(s.num_obs(), y_parts);
    namesake_.reserve(s.num_obs(), goal_parts);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        seeded_.append(y_->num_parts(ob), 0);
        bool is_pointed = pointed(s, ob);
        goal_part_.append(is_pointed ? y_->num_parts(ob) : 0, kNoPart);
        namesake_.append(is_pointed ? goal_->num_parts(ob) : 0, kNoPart);
        if (!is_pointed) {
            continue;
        }
        auto namesake = namesake_[o];
        auto goal_part = goal_part_[o];
        if (names_in_order(y, *goal_, ob)) {
            std::iota(namesake.begin(), namesake.end(), Part{0});
            std::iota(goal_part.begin(), goal_part.begin() + std::ssize(namesake), Part{0});
            continue;
        }
        for (Part p = 0; p < namesake.size(); ++p) {
            std::string_view name = goal_->part_name(ob, p);
            Part q = name.empty() ? kNoPart : y.find(ob, name);
            if (q == kNoPart) {
                return fmt::format("the subgoal's {} {} has no namesake in the target state",
                                   s.ob(ob).name, goal_->part_label(ob, p));
            }
            if (goal_part[q] != kNoPart) {
                return fmt::format("two parts of the subgoal are named {}", name);
            }
            namesake[p] = q;
            goal_part[q] = p;
        }
    }
    return std::nullopt;
}

void Focus::seed(ObId ob, Part q) {
    if (!seeded_[ob.index()][q]) {
        seeded_[ob.index()][q] = 1;
        seeds_.emplace_back(ob, q);
    }
}

// The columns of an object's homs and attributes, in the subgoal and in Y, that find_seeds reads
// part by part (looked up once per object, not once per part).
struct Focus::Columns {
    struct Hom {
        HomId f;
        std::span<const Part> goal, y;
        std::span<const Part> namesake; // of the hom's codomain
    };

    struct Attr {
        std::span<const Value> goal, y;
    };

    std::vector<Hom> homs;
    std::vector<Attr> attrs;

    // Reads ob's columns, in place of the last object's (the vectors keep their room).
    void read(const ACSet& goal, const ACSet& y, ObId ob, const Rows<Part>& namesake) {
        const auto& s = y.schema();
        homs.clear();
        attrs.clear();
        for (HomId f : s.homs_from(ob)) {
            homs.push_back({f, goal.column(f), y.column(f), namesake[s.hom(f).codom.index()]});
        }
        for (AttrId a : s.attrs_from(ob)) {
            attrs.push_back({goal.column(a), y.column(a)});
        }
    }

    // Whether part q of Y has the hom values (by namesakes) and concrete attribute values of
    // the subgoal's part p.
    bool same(Part p, Part q) const {
        for (const auto& h : homs) {
            Part t = h.goal[p];
            if (t != kNoPart && h.namesake[t] != h.y[q]) {
                return false;
            }
        }
        for (const auto& a : attrs) {
            if (!value_agrees(a.goal[p], a.y[q])) {
                return false;
            }
        }
        return true;
    }
};

// The parts of Y that differ from their namesakes in the subgoal (with the parts the subgoal's
// homs point to from them), and the arguments of the subgoal's facts that Y lacks. A scan for the
// first difference reads the objects of facts first: a step adds and deletes facts far more
// often than it changes the parts they hold.
void Focus::find_seeds() {
    const auto& s = y_->schema();
    Columns cols;
    if (scan_ == Scan::Whole) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            seed_object(ObId(o), cols);
        }
        return;
    }
    for (bool facts : {true, false}) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            if (pointed(s, ObId(o)) != facts && seed_object(ObId(o), cols)) {
                return;
            }
        }
    }
}

// Seeds what differs at ob; true when the scan is for the first difference and found one.
bool Focus::seed_object(ObId ob, Columns& cols) {
    const auto& s = y_->schema();
    std::uint32_t o = ob.index();
    if (goal_->num_parts(ob) == 0) {
        return false;
    }
    cols.read(*goal_, *y_, ob, namesake_);
    bool is_pointed = pointed(s, ob);
    // A step appends what it creates, so a part Y lacks is most often among the subgoal's
    // last: a scan for the first difference reads the parts from the end.
    bool backwards = scan_ == Scan::FirstDifference;
    Part n = static_cast<Part>(goal_->num_parts(ob));
    for (Part k = 0; k < n; ++k) {
        Part p = backwards ? n - 1 - k : k;
        bool differs = false;
        if (is_pointed) {
            Part q = namesake_[o][p];
            differs = !cols.same(p, q);
            if (differs) {
                seed(ob, q);
            }
        } else {
            Part q = fact_in_y(ob, cols, p);
            differs = q == kNoPart;
            lacks_fact_ = lacks_fact_ || differs;
            if (!differs && seeded_[o][q]++) {
                shared_fact_ = true; // two facts of the subgoal are one fact of Y
            }
        }
        if (!differs) {
            continue;
        }
        for (const auto& h : cols.homs) {
            Part t = h.goal[p];
            if (t != kNoPart) {
                seed(s.hom(h.f).codom, h.namesake[t]);
            }
        }
        if (scan_ == Scan::FirstDifference) {
            return true;
        }
    }
    return false;
}

// A part of Y of ob (nothing points into ob) with the hom values of the subgoal's part p (by
// namesakes) and its concrete attribute values, or kNoPart.
Part Focus::fact_in_y(ObId ob, const Columns& cols, Part p) const {
    for (const auto& h : cols.homs) {
        Part t = h.goal[p];
        if (t == kNoPart) {
            continue;
        }
        for (Part q : y_->incident(h.f, h.namesake[t])) {
            if (cols.same(p, q)) {
                return q;
            }
        }
        return kNoPart;
    }
    for (Part q = 0; q < y_->num_parts(ob); ++q) {
        if (cols.same(p, q)) {
            return q;
        }
    }
    return kNoPart;
}

FocusedProblem Focus::problem(std::size_t radius) const {
    CATPLAN_ASSERT(scan_ == Scan::Whole, "a focused problem needs every seed");
    const auto& s = y_->schema();
    std::vector<std::vector<char>> keep(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        keep[o].assign(y_->num_parts(ObId(o)), 0);
    }
    // Breadth-first from the seeds, `radius` steps (homs either way, facts holding both).
    std::deque<std::pair<std::pair<ObId, Part>, std::size_t>> queue;
    for (auto sd : seeds_) {
        keep[sd.first.index()][sd.second] = 1;
        queue.push_back({sd, 0});
    }
    auto reach = [&](ObId ob, Part q, std::size_t d) {
        if (q != kNoPart && !keep[ob.index()][q]) {
            keep[ob.index()][q] = 1;
            queue.push_back({{ob, q}, d});
        }
    };
    while (!queue.empty()) {
        auto [part, d] = queue.front();
        queue.pop_front();
        auto [ob, q] = part;
        if (d >= radius) {
            continue;
        }
        for (HomId f : s.homs_from(ob)) {
            reach(s.hom(f).codom, y_->subpart(f, q), d + 1);
        }
        for (HomId f : s.homs_into(ob)) {
            ObId dom = s.hom(f).dom;
            for (Part a : y_->incident(f, q)) {
                if (pointed(s, dom)) {
                    reach(dom, a, d + 1);
                    continue;
                }
                for (HomId g : s.homs_from(dom)) {
                    reach(s.hom(g).codom, y_->subpart(g, a), d + 1);
                }
            }
        }
    }
    close(keep);
    return make_problem(std::move(keep));
}

// Adds what the kept parts point to, in Y and (through namesakes) in the subgoal.
void Focus::close(std::vector<std::vector<char>>& keep) const {
    const auto& s = y_->schema();
    std::vector<std::pair<ObId, Part>> work;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        if (!pointed(s, ObId(o))) {
            continue;
        }
        for (Part q = 0; q < keep[o].size(); ++q) {
            if (keep[o][q]) {
                work.emplace_back(ObId(o), q);
            }
        }
    }
    auto add = [&](ObId ob, Part q) {
        if (q != kNoPart && !keep[ob.index()][q]) {
            keep[ob.index()][q] = 1;
            work.emplace_back(ob, q);
        }
    };
    while (!work.empty()) {
        auto [ob, q] = work.back();
        work.pop_back();
        Part p = goal_part_[ob.index()][q];
        for (HomId f : s.homs_from(ob)) {
            ObId c = s.hom(f).codom;
            add(c, y_->subpart(f, q));
            if (p != kNoPart && goal_->subpart(f, p) != kNoPart) {
                add(c, namesake_[c.index()][goal_->subpart(f, p)]);
            }
        }
    }
}

// The kept parts of Y (with the facts among them) and the subgoal's parts on them.
FocusedProblem Focus::make_problem(std::vector<std::vector<char>> keep) const {
    const auto& s = y_->schema();
    std::vector<std::vector<char>> keep_goal(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        keep_goal[o].assign(goal_->num_parts(ob), 0);
        if (pointed(s, ob)) {
            for (Part p = 0; p < goal_->num_parts(ob); ++p) {
                keep_goal[o][p] = keep[o][namesake_[o][p]];
            }
            continue;
        }
        // A fact is kept when every argument is.
        auto args_kept = [&](const ACSet& x, Part q, bool in_goal) {
            for (HomId f : s.homs_from(ob)) {
                Part t = x.subpart(f, q);
                ObId c = s.hom(f).codom;
                if (t != kNoPart && !keep[c.index()][in_goal ? namesake_[c.index()][t] : t]) {
                    return false;
                }
            }
            return true;
        };
        for (Part q = 0; q < y_->num_parts(ob); ++q) {
            keep[o][q] = args_kept(*y_, q, false) ? 1 : 0;
        }
        for (Part p = 0; p < goal_->num_parts(ob); ++p) {
            keep_goal[o][p] = args_kept(*goal_, p, true) ? 1 : 0;
        }
    }
    FocusedProblem out{induced(*y_, keep), induced(*goal_, keep_goal)};
    out.whole = true;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (char k : keep[o]) {
            out.whole = out.whole && k;
            out.parts += (k && pointed(s, ObId(o))) ? 1 : 0;
        }
    }
    return out;
}

} // namespace catplan::transfer
