#include "catplan/pddl/analysis.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/base/union_find.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <deque>
#include <fmt/format.h>
#include <map>
#include <set>

namespace catplan::pddl {

namespace {

/// Which argument positions of a fact name one object: out[i] is the first position naming
/// the object of position i.
using ArgPattern = std::vector<std::size_t>;

bool same_atom(const Atom& a, const Atom& b) {
    return a.predicate == b.predicate && a.args == b.args;
}

// ---- lifted atoms over an action's terms ------------------------------------------------------

/// An atom of an action with its arguments as indices into action_terms.
struct TermAtom {
    std::string predicate;
    std::vector<std::size_t> args;
    auto operator<=>(const TermAtom&) const = default;
};

std::size_t term_index(const std::vector<ActionTerm>& terms, const Term& t) {
    for (std::size_t i = 0; i < terms.size(); ++i) {
        if (terms[i].name == t.name && terms[i].constant == !t.variable) {
            return i;
        }
    }
    CATPLAN_ASSERT(false, "an action's atom names a term it does not have");
    return 0;
}

TermAtom term_atom(const std::vector<ActionTerm>& terms, const Atom& a) {
    TermAtom out{a.predicate, {}};
    for (const auto& t : a.args) {
        out.args.push_back(term_index(terms, t));
    }
    return out;
}

/// Per pair of terms, whether one object can be of both their types (Domain::may_share, which
/// may look at every type: computed once per action).
std::vector<std::vector<char>> sharing(const Domain& d, const std::vector<ActionTerm>& terms) {
    std::vector<std::vector<char>> out(terms.size(), std::vector<char>(terms.size(), 1));
    for (std::size_t x = 0; x < terms.size(); ++x) {
        for (std::size_t y = x + 1; y < terms.size(); ++y) {
            out[x][y] = out[y][x] = d.may_share(terms[x].type, terms[y].type) ? 1 : 0;
        }
    }
    return out;
}

/// An action read over its terms, with what the invariant check needs.
struct LiftedAction {
    std::vector<ActionTerm> terms;
    std::vector<std::vector<char>> share; // sharing(terms)
    std::vector<TermAtom> pos, add, del;
    std::set<std::pair<std::size_t, std::size_t>> distinct; // (not (= x y)), x < y

    bool in_pos(const TermAtom& a) const {
        return std::find(pos.begin(), pos.end(), a) != pos.end();
    }

    /// Whether two terms may name one object in some binding.
    bool may_equal(std::size_t x, std::size_t y) const {
        if (x == y) {
            return true;
        }
        const auto &s = terms[x], &t = terms[y];
        if (s.constant && t.constant) {
            return false;
        }
        if (share[x][y] == 0) {
            return false;
        }
        return distinct.count({std::min(x, y), std::max(x, y)}) == 0;
    }

    bool may_equal(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) const {
        if (a.size() != b.size()) {
            return false;
        }
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (!may_equal(a[i], b[i])) {
                return false;
            }
        }
        return true;
    }

    bool may_equal(const TermAtom& a, const TermAtom& b) const {
        return a.predicate == b.predicate && may_equal(a.args, b.args);
    }
};

LiftedAction lift(const Domain& d, const Action& a) {
    LiftedAction out;
    out.terms = action_terms(d, a);
    out.share = sharing(d, out.terms);
    for (const auto& l : a.precondition) {
        if (l.atom.predicate == "=") {
            if (!l.positive) {
                std::size_t x = term_index(out.terms, l.atom.args[0]);
                std::size_t y = term_index(out.terms, l.atom.args[1]);
                out.distinct.insert({std::min(x, y), std::max(x, y)});
            }
        } else if (l.positive) {
            out.pos.push_back(term_atom(out.terms, l.atom));
        }
    }
    for (const auto& at : a.add) {
        out.add.push_back(term_atom(out.terms, at));
    }
    for (const auto& at : a.del) {
        out.del.push_back(term_atom(out.terms, at));
    }
    return out;
}

template <class Args>
std::vector<std::size_t> instance(const Args& args, const InvariantPart& p) {
    std::vector<std::size_t> out;
    for (std::size_t i : p.order) {
        out.push_back(args[i]);
    }
    return out;
}

// ---- invariant synthesis ----------------------------------------------------------------------

/// A canonical key: the parts sorted by predicate, parameters renumbered by first use.
std::string key_of(const Invariant& inv) {
    auto parts = inv.parts;
    std::sort(parts.begin(), parts.end(),
              [](const auto& a, const auto& b) { return a.predicate < b.predicate; });
    std::vector<int> renumber(inv.arity, -1);
    int next = 0;
    std::string key;
    for (const auto& p : parts) {
        // Per argument position: the renumbered parameter, or * for the counted one.
        std::size_t n = p.order.size() + (p.counted >= 0 ? 1 : 0);
        std::vector<std::string> pos;
        for (std::size_t k = 0; k < n; ++k) {
            auto it = std::find(p.order.begin(), p.order.end(), k);
            if (it == p.order.end()) {
                pos.emplace_back("*");
                continue;
            }
            auto& r = renumber[static_cast<std::size_t>(it - p.order.begin())];
            if (r < 0) {
                r = next++;
            }
            pos.push_back(std::to_string(r));
        }
        key += fmt::format("{}({});", p.predicate, fmt::join(pos, ","));
    }
    return key;
}

enum class Check { Holds, Fails, Grow };

class InvariantFinder {
public:
    explicit InvariantFinder(const Domain& d) : d_(d) {
        for (const auto& a : d.actions) {
            actions_.push_back(lift(d, a));
        }
    }

    std::vector<Invariant> run() {
        std::set<std::string> fluent;
        for (const auto& a : actions_) {
            for (const auto& e : a.add) {
                fluent.insert(e.predicate);
            }
        }
        for (const auto& p : d_.predicates) {
            if (fluent.count(p.name) == 0) {
                continue;
            }
            std::size_t n = p.params.size();
            for (int counted = -1; counted < static_cast<int>(n); ++counted) {
                InvariantPart part{p.name, {}, counted};
                for (std::size_t i = 0; i < n; ++i) {
                    if (static_cast<int>(i) != counted) {
                        part.order.push_back(i);
                    }
                }
                enqueue(Invariant{part.order.size(), {part}});
            }
        }
        std::vector<Invariant> out;
        while (!queue_.empty() && checked_ < kMaxCandidates) {
            Invariant inv = std::move(queue_.front());
            queue_.pop_front();
            ++checked_;
            if (check(inv)) {
                out.push_back(std::move(inv));
            }
        }
        std::stable_sort(out.begin(), out.end(), [](const Invariant& a, const Invariant& b) {
            return a.parts.size() < b.parts.size();
        });
        return out;
    }

private:
    static constexpr std::size_t kMaxCandidates = 5000;
    static constexpr std::size_t kMaxParts = 5;

    void enqueue(Invariant inv) {
        if (seen_.insert(key_of(inv)).second) {
            queue_.push_back(std::move(inv));
        }
    }

    /// Whether every action keeps the invariant; grows the candidate where one does not.
    bool check(const Invariant& inv) {
        for (const auto& a : actions_) {
            if (!balanced(inv, a)) {
                return false;
            }
        }
        return true;
    }

    struct Added {
        const TermAtom* atom;
        const InvariantPart* part;
        std::vector<std::size_t> params;
    };

    bool balanced(const Invariant& inv, const LiftedAction& a) {
        std::vector<Added> added;
        for (const auto& e : a.add) {
            const InvariantPart* p = inv.find(e.predicate);
            if (p != nullptr && !a.in_pos(e)) {
                added.push_back({&e, p, instance(e.args, *p)});
            }
        }
        // Two facts of one instance added at once: the count may grow by two, unless the
        // precondition could not hold where they are of one instance. A bigger candidate may
        // make it so (stack(x, x) needs (holding x) and (clear x), two facts of one instance of
        // "at most one of (clear ?b), (holding ?b), (on * ?b)").
        for (std::size_t i = 0; i < added.size(); ++i) {
            for (std::size_t j = i + 1; j < added.size(); ++j) {
                const auto &x = added[i], &y = added[j];
                bool same_fact = x.part == y.part && x.part->counted < 0;
                if (!same_fact && a.may_equal(x.params, y.params) &&
                    !excluded(inv, a, x.params, y.params)) {
                    grow(inv, a, x.params);
                    grow(inv, a, y.params);
                    return false;
                }
            }
        }
        for (const auto& e : added) {
            bool ok = std::any_of(a.del.begin(), a.del.end(), [&](const TermAtom& d) {
                const InvariantPart* q = inv.find(d.predicate);
                return q != nullptr && sure_delete(inv, a, d) && instance(d.args, *q) == e.params;
            });
            if (!ok) {
                grow(inv, a, e.params);
                return false;
            }
        }
        return true;
    }

    /// Whether the action cannot apply, in a state where inv holds, with the terms xs[i] and
    /// ys[i] naming one object: its precondition would then hold facts of two predicates in one
    /// instance of inv (facts of two predicates stay two however more terms are identified).
    /// This assumes inv in the state before, as the induction that proves inv may.
    static bool excluded(const Invariant& inv, const LiftedAction& a,
                         const std::vector<std::size_t>& xs, const std::vector<std::size_t>& ys) {
        UnionFind same(a.terms.size());
        for (std::size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
            same.union_sets(static_cast<std::uint32_t>(xs[i]), static_cast<std::uint32_t>(ys[i]));
        }
        std::vector<std::pair<const std::string*, std::vector<std::size_t>>> facts;
        for (const auto& p : a.pos) {
            const InvariantPart* part = inv.find(p.predicate);
            if (part == nullptr) {
                continue;
            }
            std::vector<std::size_t> args;
            for (std::size_t t : p.args) {
                args.push_back(same.find(static_cast<std::uint32_t>(t)));
            }
            auto params = instance(args, *part);
            for (const auto& [predicate, other] : facts) {
                if (*predicate != p.predicate && other == params) {
                    return true;
                }
            }
            facts.emplace_back(&p.predicate, std::move(params));
        }
        return false;
    }

    /// A delete that surely removes a fact that held: in the precondition, and no add puts it
    /// back (an add that could only where the action cannot apply, excluded, does not).
    static bool sure_delete(const Invariant& inv, const LiftedAction& a, const TermAtom& d) {
        return a.in_pos(d) && std::none_of(a.add.begin(), a.add.end(), [&](const TermAtom& e) {
                   return a.may_equal(e, d) && !excluded(inv, a, e.args, d.args);
               });
    }

    /// The candidates that add a predicate the action surely deletes, with the parameters of
    /// an add that nothing balanced.
    void grow(const Invariant& inv, const LiftedAction& a, const std::vector<std::size_t>& params) {
        if (inv.parts.size() >= kMaxParts) {
            return;
        }
        for (const auto& d : a.del) {
            if (inv.find(d.predicate) != nullptr || !sure_delete(inv, a, d)) {
                continue;
            }
            InvariantPart q{d.predicate, {}, -1};
            std::vector<bool> used(d.args.size(), false);
            bool ok = true;
            for (std::size_t t : params) {
                auto it = std::find(d.args.begin(), d.args.end(), t);
                ok = ok && it != d.args.end();
                if (ok) {
                    std::size_t pos = static_cast<std::size_t>(it - d.args.begin());
                    q.order.push_back(pos);
                    used[pos] = true;
                }
            }
            std::size_t rest =
                static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
            if (!ok || rest > 1) {
                continue;
            }
            if (rest == 1) {
                q.counted =
                    static_cast<int>(std::find(used.begin(), used.end(), false) - used.begin());
            }
            Invariant bigger = inv;
            bigger.parts.push_back(std::move(q));
            enqueue(std::move(bigger));
        }
    }

    const Domain& d_;
    std::vector<LiftedAction> actions_;
    std::deque<Invariant> queue_;
    std::set<std::string> seen_;
    std::size_t checked_ = 0;
};

// ---- identifications ---------------------------------------------------------------------------

/// The pattern of a fact over blocks.
ArgPattern block_pattern(const std::vector<std::size_t>& args) {
    ArgPattern out(args.size());
    for (std::size_t i = 0; i < args.size(); ++i) {
        out[i] =
            static_cast<std::size_t>(std::find(args.begin(), args.end(), args[i]) - args.begin());
    }
    return out;
}

class Identifications {
public:
    Identifications(const Domain& d, const Action& a)
        : d_(d), a_(a), terms_(action_terms(d, a)), share_(sharing(d, terms_)) {}

    /// Every identification the types and the equality literals allow, with its facts; those
    /// with a contradictory precondition are left out.
    std::vector<Identification> all() {
        std::vector<std::size_t> block(terms_.size(), 0);
        partitions(0, 0, block);
        return std::move(out_);
    }

private:
    void partitions(std::size_t i, std::size_t nblocks, std::vector<std::size_t>& block) {
        if (i == terms_.size()) {
            add(block, nblocks);
            return;
        }
        for (std::size_t b = 0; b <= nblocks; ++b) {
            block[i] = b;
            if (fits(i, block)) {
                partitions(i + 1, std::max(nblocks, b + 1), block);
            }
        }
    }

    /// Whether term i may join its block: types an object can have at once, at most one
    /// constant, a constant's type below every parameter's type, and the equality literals so
    /// far respected.
    bool fits(std::size_t i, const std::vector<std::size_t>& block) const {
        for (std::size_t j = 0; j < i; ++j) {
            if (block[j] != block[i]) {
                continue;
            }
            const auto &s = terms_[i], &t = terms_[j];
            if (s.constant && t.constant) {
                return false;
            }
            if ((s.constant && !d_.is_subtype(s.type, t.type)) ||
                (t.constant && !d_.is_subtype(t.type, s.type))) {
                return false;
            }
            if (share_[i][j] == 0) {
                return false;
            }
        }
        for (const auto& l : a_.precondition) {
            if (l.atom.predicate != "=") {
                continue;
            }
            std::size_t x = term_index(terms_, l.atom.args[0]);
            std::size_t y = term_index(terms_, l.atom.args[1]);
            if (x <= i && y <= i && (block[x] == block[y]) != l.positive) {
                return false;
            }
        }
        return true;
    }

    BlockFact fact(const Atom& atom, const std::vector<std::size_t>& block) const {
        BlockFact f{atom.predicate, {}};
        for (const auto& t : atom.args) {
            f.args.push_back(block[term_index(terms_, t)]);
        }
        return f;
    }

    void add(const std::vector<std::size_t>& block, std::size_t nblocks) {
        std::set<BlockFact> pos, neg, add, del;
        for (const auto& l : a_.precondition) {
            if (l.atom.predicate != "=") {
                (l.positive ? pos : neg).insert(fact(l.atom, block));
            }
        }
        for (const auto& f : pos) {
            if (neg.count(f) != 0) {
                return; // contradictory precondition under this identification
            }
        }
        for (const auto& at : a_.add) {
            add.insert(fact(at, block));
        }
        for (const auto& at : a_.del) {
            if (add.count(fact(at, block)) == 0) {
                del.insert(fact(at, block));
            }
        }
        out_.push_back({block,
                        nblocks,
                        {pos.begin(), pos.end()},
                        {neg.begin(), neg.end()},
                        {add.begin(), add.end()},
                        {del.begin(), del.end()}});
    }

    const Domain& d_;
    const Action& a_;
    std::vector<ActionTerm> terms_;
    std::vector<std::vector<char>> share_;
    std::vector<Identification> out_;
};

/// Whether two different facts are in one instance of an invariant.
bool mutex(const std::vector<Invariant>& invariants, const BlockFact& x, const BlockFact& y) {
    if (x == y) {
        return false;
    }
    for (const auto& inv : invariants) {
        const InvariantPart* p = inv.find(x.predicate);
        const InvariantPart* q = inv.find(y.predicate);
        if (p != nullptr && q != nullptr && instance(x.args, *p) == instance(y.args, *q)) {
            return true;
        }
    }
    return false;
}

bool mutex_with_any(const std::vector<Invariant>& invariants, const BlockFact& f,
                    const std::vector<BlockFact>& facts) {
    return std::any_of(facts.begin(), facts.end(),
                       [&](const BlockFact& g) { return mutex(invariants, f, g); });
}

} // namespace

// ---- public -------------------------------------------------------------------------------------

std::string Invariant::to_string() const {
    std::vector<std::string> facts;
    for (const auto& p : parts) {
        std::vector<std::string> args(p.order.size() + (p.counted >= 0 ? 1 : 0), "*");
        for (std::size_t i = 0; i < p.order.size(); ++i) {
            args[p.order[i]] = fmt::format("?{}", i + 1);
        }
        facts.push_back(args.empty() ? "(" + p.predicate + ")"
                                     : fmt::format("({} {})", p.predicate, fmt::join(args, " ")));
    }
    return fmt::format("at most one of {}", fmt::join(facts, ", "));
}

const InvariantPart* Invariant::find(std::string_view predicate) const {
    for (const auto& p : parts) {
        if (p.predicate == predicate) {
            return &p;
        }
    }
    return nullptr;
}

std::vector<Invariant> find_invariants(const Domain& domain) {
    return InvariantFinder(domain).run();
}

bool holds_in(const Invariant& invariant, const std::vector<Atom>& facts) {
    // Each counted fact under its key, the names of the arguments the invariant keeps fixed, each
    // after its length: sorted, the facts of one key are neighbours, and all must be one fact. A
    // key of short names needs no memory of its own.
    std::vector<std::pair<std::string, const Atom*>> keyed;
    for (const auto& f : facts) {
        const InvariantPart* p = invariant.find(f.predicate);
        if (p == nullptr) {
            continue;
        }
        std::string key;
        for (std::size_t i : p->order) {
            const std::string& name = f.args[i].name;
            std::array<char, 24> digits{};
            auto end = std::to_chars(digits.data(), digits.data() + digits.size(), name.size()).ptr;
            key.append(digits.data(), end);
            key += ':';
            key += name;
        }
        keyed.emplace_back(std::move(key), &f);
    }
    std::sort(keyed.begin(), keyed.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 1; k < keyed.size(); ++k) {
        if (keyed[k].first == keyed[k - 1].first &&
            !same_atom(*keyed[k].second, *keyed[k - 1].second)) {
            return false;
        }
    }
    return true;
}

namespace {

ArgPattern pattern_of(const Atom& atom) {
    ArgPattern out(atom.args.size());
    for (std::size_t i = 0; i < atom.args.size(); ++i) {
        std::size_t j = 0;
        while (!(atom.args[j] == atom.args[i])) {
            ++j;
        }
        out[i] = j;
    }
    return out;
}

ArgPattern distinct_pattern(std::size_t arity) {
    ArgPattern out(arity);
    for (std::size_t i = 0; i < arity; ++i) {
        out[i] = i;
    }
    return out;
}

} // namespace

std::vector<ActionTerm> action_terms(const Domain& domain, const Action& action) {
    std::vector<ActionTerm> terms;
    for (const auto& p : action.params) {
        terms.push_back({p.name, p.type, false});
    }
    auto note_constants = [&](const Atom& atom) {
        for (const auto& t : atom.args) {
            bool known = std::any_of(terms.begin(), terms.end(), [&](const ActionTerm& x) {
                return x.name == t.name && x.constant == !t.variable;
            });
            if (!t.variable && !known) {
                for (const auto& c : domain.constants) {
                    if (c.name == t.name) {
                        terms.push_back({c.name, c.type, true});
                    }
                }
            }
        }
    };
    for (const auto& l : action.precondition) {
        note_constants(l.atom);
    }
    for (const auto& l : action.add) {
        note_constants(l);
    }
    for (const auto& l : action.del) {
        note_constants(l);
    }
    return terms;
}

Assumptions domain_assumptions(const Domain& domain) {
    Assumptions a;
    a.invariants = find_invariants(domain);
    return a;
}

Assumptions assumptions_for(const Domain& domain, const Assumptions& base,
                            const std::vector<Atom>& initial) {
    Assumptions out;
    for (const auto& inv : base.invariants) {
        if (holds_in(inv, initial)) {
            out.invariants.push_back(inv);
        } else {
            out.broken.push_back(
                fmt::format("the initial state breaks the invariant {}", inv.to_string()));
        }
    }
    std::map<std::string, std::set<ArgPattern>> patterns;
    bool repeated = false;
    for (const auto& f : initial) {
        ArgPattern p = pattern_of(f);
        repeated = repeated || p != distinct_pattern(p.size());
        patterns[f.predicate].insert(p);
    }
    if (!repeated && base.patterns.empty()) {
        return out; // the domain's assumption holds: initial facts name distinct objects
    }
    if (repeated) {
        out.broken.push_back("an initial fact names one object twice");
    }
    for (const auto& p : domain.predicates) {
        auto it = patterns.find(p.name);
        std::vector<std::vector<std::size_t>> list;
        if (it != patterns.end()) {
            list.assign(it->second.begin(), it->second.end());
        }
        out.patterns.emplace_back(p.name, std::move(list));
    }
    return out;
}

std::vector<std::vector<Identification>>
applicable_identifications(const Domain& domain, const Assumptions& assumptions) {
    std::map<std::string, std::set<ArgPattern>> reached;
    if (assumptions.patterns.empty()) {
        for (const auto& p : domain.predicates) {
            reached[p.name].insert(distinct_pattern(p.params.size()));
        }
    } else {
        for (const auto& [pred, list] : assumptions.patterns) {
            reached[pred].insert(list.begin(), list.end());
        }
    }
    const auto& inv = assumptions.invariants;
    // Every identification of every action, less those that ask for mutex facts.
    std::vector<std::vector<Identification>> candidates;
    for (const auto& a : domain.actions) {
        auto all = Identifications(domain, a).all();
        std::erase_if(all, [&](const Identification& id) {
            for (std::size_t i = 0; i < id.pos.size(); ++i) {
                for (std::size_t j = i + 1; j < id.pos.size(); ++j) {
                    if (mutex(inv, id.pos[i], id.pos[j])) {
                        return true;
                    }
                }
            }
            return false;
        });
        candidates.push_back(std::move(all));
    }
    // The delete relaxation's fixpoint over argument patterns.
    std::vector<std::vector<bool>> applies(candidates.size());
    for (std::size_t a = 0; a < candidates.size(); ++a) {
        applies[a].assign(candidates[a].size(), false);
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t a = 0; a < candidates.size(); ++a) {
            for (std::size_t k = 0; k < candidates[a].size(); ++k) {
                const auto& id = candidates[a][k];
                if (applies[a][k]) {
                    continue;
                }
                bool ok = std::all_of(id.pos.begin(), id.pos.end(), [&](const BlockFact& f) {
                    return reached[f.predicate].count(block_pattern(f.args)) != 0;
                });
                if (!ok) {
                    continue;
                }
                applies[a][k] = true;
                changed = true;
                for (const auto& f : id.add) {
                    reached[f.predicate].insert(block_pattern(f.args));
                }
            }
        }
    }
    std::vector<std::vector<Identification>> out(candidates.size());
    for (std::size_t a = 0; a < candidates.size(); ++a) {
        for (std::size_t k = 0; k < candidates[a].size(); ++k) {
            if (!applies[a][k]) {
                continue;
            }
            Identification id = std::move(candidates[a][k]);
            std::erase_if(id.del, [&](const BlockFact& f) {
                return std::find(id.pos.begin(), id.pos.end(), f) == id.pos.end() &&
                       mutex_with_any(inv, f, id.pos);
            });
            out[a].push_back(std::move(id));
        }
    }
    return out;
}

} // namespace catplan::pddl
