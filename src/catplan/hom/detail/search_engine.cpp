#include "catplan/hom/detail/search_engine.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/base/hash.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <limits>
#include <memory>
#include <utility>

namespace catplan::hom::detail {

namespace {

using schema::Schema;

// Where the candidates of the chosen part come from: an explicit list, or all parts 0..size-1.
struct Source {
    const Part* data = nullptr;
    std::size_t size = 0;
};

// Codomain parts of one object grouped by the tuple of their hom values, so that a domain part
// whose homs all have images finds its candidates with one hash lookup. Parts are grouped by
// the 64-bit hash of the tuple: a collision only adds candidates, which assign() then rejects.
// The groups are found through an open-addressing table (linear probing, power-of-two size,
// at most half full): one probe sequence per lookup and no allocation after it is built.
struct KeyIndex {
    struct Slot {
        std::uint64_t key = 0;
        std::uint32_t begin = 0;
        std::uint32_t end = 0; // begin == end marks an empty slot (groups are never empty)
    };

    bool built = false;
    std::vector<Part> parts;
    std::vector<Slot> table;
    std::uint64_t mask = 0;

    const Slot* find(std::uint64_t key) const {
        for (std::uint64_t i = hash_mix(key) & mask;; i = (i + 1) & mask) {
            const Slot& slot = table[i];
            if (slot.begin == slot.end) {
                return nullptr;
            }
            if (slot.key == key) {
                return &slot;
            }
        }
    }

    void insert(std::uint64_t key, std::uint32_t begin, std::uint32_t end) {
        std::uint64_t i = hash_mix(key) & mask;
        while (table[i].begin != table[i].end) {
            i = (i + 1) & mask;
        }
        table[i] = Slot{key, begin, end};
    }
};

// A hom out of an object, with raw column pointers for the inner loops.
struct HomRef {
    std::uint32_t codom;
    const Part* xcol;
    const Part* ycol;
};

struct TrailEntry {
    bool is_var; // false: a part assignment (ob, x); true: a variable binding (type, var)
    std::uint32_t a;
    std::uint32_t b;
};

// The tables of a search. Matching a small rule in a state is a short search whose tables
// cost more to allocate and free than to fill, so each thread keeps the tables of its finished
// searches and the next search reuses them, sized anew (Engine::allocate); a search started
// inside another's callback takes tables of its own.
struct Tables {
    std::vector<std::vector<Part>> assign; // per object: image of each domain part
    std::vector<std::vector<Part>> inv;    // per monic object: preimage of each codom part
    std::vector<char> dense_inv;           // per monic object: inv is used (else a scan)
    std::vector<std::uint64_t> key_wanted; // per object: lookups that a key index would serve
    std::vector<char> monic;               // per object
    std::vector<std::vector<std::vector<Part>>> cand; // per object, per part: sorted allowed
    std::vector<char> has_cand;                       // per object: any candidate set given
    std::vector<std::vector<Value>> vbind;            // per type: binding of each domain variable
    std::vector<std::vector<char>> vused;             // per monic type: codomain variable taken
    std::vector<char> monic_t;                        // per attribute type
    std::vector<std::pair<std::uint32_t, std::uint32_t>> floating; // (type, var) to enumerate
    std::vector<KeyIndex> keys;                                    // per object, built on first use
    std::vector<std::vector<HomRef>> homs_out;                     // per object: the homs out of it
    std::vector<TrailEntry> trail;
    ACSetMorphism scratch;

    // Roughly the bytes held by the tables that grow with the states.
    std::size_t footprint() const {
        std::size_t n = trail.capacity() * sizeof(TrailEntry);
        for (std::size_t ob = 0; ob < assign.size(); ++ob) {
            n += (assign[ob].capacity() + (ob < inv.size() ? inv[ob].capacity() : 0)) * 4;
        }
        for (const auto& k : keys) {
            n += k.parts.capacity() * 4 + k.table.capacity() * sizeof(KeyIndex::Slot);
        }
        return n;
    }
};

// A thread's tables not in use; tables that grew past kKeptBytes (a search in a large state)
// are freed rather than kept.
class TablePool {
public:
    std::unique_ptr<Tables> acquire() {
        if (free_.empty()) {
            return std::make_unique<Tables>();
        }
        auto t = std::move(free_.back());
        free_.pop_back();
        return t;
    }

    void release(std::unique_ptr<Tables> t) {
        if (t->footprint() <= kKeptBytes) {
            free_.push_back(std::move(t));
        }
    }

private:
    static constexpr std::size_t kKeptBytes = std::size_t{1} << 20;
    std::vector<std::unique_ptr<Tables>> free_;
};

TablePool& table_pool() {
    thread_local TablePool pool;
    return pool;
}

class Engine {
public:
    Engine(const ACSet& x, const ACSet& y, const HomSearchOptions& opt, SearchMode mode,
           const std::function<bool(const ACSetMorphism&)>* fn)
        : x_(x),
          y_(y),
          s_(x.schema()),
          opt_(opt),
          mode_(mode),
          fn_(fn),
          tables_(table_pool().acquire()) {}

    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    ~Engine() { table_pool().release(std::move(tables_)); }

    HomSearchResult run();

private:
    bool prepare();
    void read_options(std::vector<char>& iso_ob, std::vector<char>& no_bind);
    bool find_floating(const std::vector<char>& no_bind);
    bool room_for(const std::vector<char>& iso_ob) const;
    void allocate();
    bool restrict_candidates();
    bool bind_initial();
    bool assign(std::uint32_t ob, Part x, Part y);
    bool taken(std::uint32_t ob, Part y) const;
    bool bind_var(std::uint32_t t, std::uint32_t v, const Value& value);
    void undo(std::size_t mark);
    bool search();
    bool enumerate_floating(std::size_t i);
    bool emit();
    std::size_t estimate(std::uint32_t ob, Part x, Source& src);
    const KeyIndex& key_index(std::uint32_t ob);
    std::uint64_t codom_key(std::uint32_t ob, Part y) const;

    const ACSet& x_;
    const ACSet& y_;
    const Schema& s_;
    const HomSearchOptions& opt_;
    SearchMode mode_;
    const std::function<bool(const ACSetMorphism&)>* fn_;

    HomSearchResult result_;
    bool stopped_ = false;

    std::unique_ptr<Tables> tables_;
    std::vector<std::vector<Part>>& assign_ = tables_->assign;
    std::vector<std::vector<Part>>& inv_ = tables_->inv;
    std::vector<char>& dense_inv_ = tables_->dense_inv;
    std::vector<std::uint64_t>& key_wanted_ = tables_->key_wanted;
    std::vector<char>& monic_ = tables_->monic;
    std::vector<std::vector<std::vector<Part>>>& cand_ = tables_->cand;
    std::vector<char>& has_cand_ = tables_->has_cand;
    std::vector<std::vector<Value>>& vbind_ = tables_->vbind;
    std::vector<std::vector<char>>& vused_ = tables_->vused;
    std::vector<char>& monic_t_ = tables_->monic_t;
    std::vector<std::pair<std::uint32_t, std::uint32_t>>& floating_ = tables_->floating;
    std::vector<KeyIndex>& keys_ = tables_->keys;
    std::vector<std::vector<HomRef>>& homs_out_ = tables_->homs_out;
    std::size_t unassigned_ = 0; // domain parts without an image
    std::vector<TrailEntry>& trail_ = tables_->trail;
    ACSetMorphism& scratch_ = tables_->scratch;
};

std::uint64_t Engine::codom_key(std::uint32_t ob, Part y) const {
    std::uint64_t h = 0x51ed270b27e1f2c3ULL;
    for (const HomRef& f : homs_out_[ob]) {
        h = hash_combine(h, f.ycol[y]);
    }
    return h;
}

const KeyIndex& Engine::key_index(std::uint32_t ob) {
    KeyIndex& k = keys_[ob];
    if (k.built) {
        return k;
    }
    k.built = true;
    std::size_t n = y_.num_parts(ObId(ob));
    std::vector<std::pair<std::uint64_t, Part>> keyed(n);
    for (Part p = 0; p < n; ++p) {
        keyed[p] = {codom_key(ob, p), p};
    }
    // Sorting by (key, part) keeps each group in increasing part order: results stay ordered.
    std::sort(keyed.begin(), keyed.end());
    k.parts.resize(n);
    std::size_t size = 16;
    while (size < 2 * n) {
        size *= 2;
    }
    k.table.assign(size, {});
    k.mask = size - 1;
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i;
        while (j < n && keyed[j].first == keyed[i].first) {
            k.parts[j] = keyed[j].second;
            ++j;
        }
        k.insert(keyed[i].first, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
        i = j;
    }
    return k;
}

bool Engine::bind_var(std::uint32_t t, std::uint32_t v, const Value& value) {
    Value& b = vbind_[t][v];
    if (!b.is_unset()) {
        return b == value;
    }
    if (value.is_unset()) {
        return false; // a variable needs a value to bind to
    }
    if (monic_t_[t]) {
        if (!value.is_var() || value.var_index() >= vused_[t].size() ||
            vused_[t][value.var_index()]) {
            return false;
        }
        vused_[t][value.var_index()] = 1;
    }
    b = value;
    trail_.push_back({true, t, v});
    return true;
}

bool Engine::taken(std::uint32_t ob, Part y) const {
    if (dense_inv_[ob]) {
        return inv_[ob][y] != kNoPart;
    }
    const auto& a = assign_[ob];
    return std::find(a.begin(), a.end(), y) != a.end();
}

bool Engine::assign(std::uint32_t ob, Part x, Part y) {
    Part cur = assign_[ob][x];
    if (cur != kNoPart) {
        return cur == y;
    }
    if (has_cand_[ob]) {
        const auto& allowed = cand_[ob][x];
        if (!allowed.empty() && !std::binary_search(allowed.begin(), allowed.end(), y)) {
            return false;
        }
    }
    if (monic_[ob] && taken(ob, y)) {
        return false;
    }
    if (opt_.accept && !opt_.accept(ObId(ob), x, y)) {
        return false;
    }
    // Attributes first: they fail fast and need no recursion.
    for (AttrId a : s_.attrs_from(ObId(ob))) {
        const Value& xv = x_.subpart(a, x);
        const Value& yv = y_.subpart(a, y);
        if (xv.is_unset()) {
            if (opt_.iso && !yv.is_unset()) {
                return false;
            }
            continue; // an unset domain cell constrains nothing
        }
        if (xv.is_concrete()) {
            if (!(xv == yv)) {
                return false;
            }
            continue;
        }
        if (!bind_var(s_.attr(a).codom.index(), xv.var_index(), yv)) {
            return false;
        }
    }
    assign_[ob][x] = y;
    if (monic_[ob] && dense_inv_[ob]) {
        inv_[ob][y] = x;
    }
    trail_.push_back({false, ob, x});
    --unassigned_;
    // Forward checking: the images of x's hom values are now determined.
    for (const HomRef& f : homs_out_[ob]) {
        Part xf = f.xcol[x];
        Part yf = f.ycol[y];
        if (xf == kNoPart) {
            if (opt_.iso && yf != kNoPart) {
                return false;
            }
            continue; // an unset domain hom value constrains nothing
        }
        if (yf == kNoPart || !assign(f.codom, xf, yf)) {
            return false;
        }
    }
    return true;
}

void Engine::undo(std::size_t mark) {
    while (trail_.size() > mark) {
        TrailEntry e = trail_.back();
        trail_.pop_back();
        if (e.is_var) {
            Value& b = vbind_[e.a][e.b];
            if (monic_t_[e.a] && b.is_var()) {
                vused_[e.a][b.var_index()] = 0;
            }
            b = Value();
        } else {
            Part& y = assign_[e.a][e.b];
            if (monic_[e.a] && dense_inv_[e.a]) {
                inv_[e.a][y] = kNoPart;
            }
            y = kNoPart;
            ++unassigned_;
        }
    }
}

std::size_t Engine::estimate(std::uint32_t ob, Part x, Source& src) {
    src = Source{nullptr, y_.num_parts(ObId(ob))};
    if (has_cand_[ob] && !cand_[ob][x].empty()) {
        src = Source{cand_[ob][x].data(), cand_[ob][x].size()};
    }
    const auto& homs = homs_out_[ob];
    if (homs.empty()) {
        return src.size;
    }
    bool all_assigned = true;
    for (const HomRef& f : homs) {
        Part xf = f.xcol[x];
        if (xf == kNoPart || assign_[f.codom][xf] == kNoPart) {
            all_assigned = false;
            break;
        }
    }
    // The composite-key index costs O(|Y| log |Y|) to build: build it once enough lookups would
    // use it (triangle counting: at once; one rule match in a large state: never).
    if (all_assigned && homs.size() >= 2 && !keys_[ob].built &&
        ++key_wanted_[ob] * 8 < y_.num_parts(ObId(ob))) {
        all_assigned = false;
    }
    if (all_assigned && homs.size() >= 2) {
        std::uint64_t h = 0x51ed270b27e1f2c3ULL;
        for (const HomRef& f : homs) {
            h = hash_combine(h, assign_[f.codom][f.xcol[x]]);
        }
        const KeyIndex& k = key_index(ob);
        const KeyIndex::Slot* slot = k.find(h);
        if (slot == nullptr) {
            src = Source{k.parts.data(), 0};
            return 0;
        }
        std::size_t n = slot->end - slot->begin;
        if (n < src.size) {
            src = Source{k.parts.data() + slot->begin, n};
        }
        return src.size;
    }
    auto hom_ids = s_.homs_from(ObId(ob));
    for (std::size_t i = 0; i < homs.size(); ++i) {
        Part xf = homs[i].xcol[x];
        if (xf == kNoPart) {
            continue;
        }
        Part img = assign_[homs[i].codom][xf];
        if (img == kNoPart) {
            continue;
        }
        auto inc = y_.incident(hom_ids[i], img);
        if (inc.size() < src.size) {
            src = Source{inc.data(), inc.size()};
        }
    }
    return src.size;
}

bool Engine::search() {
    // Choose the unassigned part with the fewest candidates (ties: object order, part order).
    if (unassigned_ == 0) {
        return enumerate_floating(0);
    }
    std::size_t best = std::numeric_limits<std::size_t>::max();
    std::uint32_t best_ob = 0;
    Part best_x = kNoPart;
    Source best_src;
    for (std::uint32_t ob = 0; ob < assign_.size() && best > 0; ++ob) {
        const auto& a = assign_[ob];
        for (Part x = 0; x < a.size(); ++x) {
            if (a[x] != kNoPart) {
                continue;
            }
            Source src;
            std::size_t n = estimate(ob, x, src);
            if (n < best) {
                best = n;
                best_ob = ob;
                best_x = x;
                best_src = src;
                if (n == 0) {
                    break;
                }
            }
        }
    }
    if (best_x == kNoPart) {
        return enumerate_floating(0);
    }
    for (std::size_t i = 0; i < best_src.size; ++i) {
        Part y = best_src.data ? best_src.data[i] : static_cast<Part>(i);
        if (opt_.node_limit != 0 && result_.stats.nodes >= opt_.node_limit) {
            stopped_ = true;
            return false;
        }
        ++result_.stats.nodes;
        std::size_t mark = trail_.size();
        if (assign(best_ob, best_x, y) && !search()) {
            undo(mark);
            return false;
        }
        undo(mark);
    }
    return true;
}

bool Engine::enumerate_floating(std::size_t i) {
    if (i == floating_.size()) {
        return emit();
    }
    auto [t, v] = floating_[i];
    std::size_t n = y_.num_vars(AttrTypeId(t));
    for (std::uint32_t k = 0; k < n; ++k) {
        std::size_t mark = trail_.size();
        if (bind_var(t, v, Value::var(k)) && !enumerate_floating(i + 1)) {
            undo(mark);
            return false;
        }
        undo(mark);
    }
    return true;
}

bool Engine::emit() {
    ++result_.count;
    if (mode_ != SearchMode::Count) {
        // Reuse the scratch morphism's buffers: no allocation per result in Callback mode.
        scratch_.components.resize(assign_.size());
        for (std::size_t ob = 0; ob < assign_.size(); ++ob) {
            scratch_.components[ob].assign(assign_[ob].begin(), assign_[ob].end());
        }
        scratch_.var_components.resize(vbind_.size());
        for (std::size_t t = 0; t < vbind_.size(); ++t) {
            scratch_.var_components[t].assign(vbind_[t].begin(), vbind_[t].end());
        }
        if (mode_ == SearchMode::Collect) {
            result_.morphisms.push_back(scratch_);
        } else if (!(*fn_)(scratch_)) {
            stopped_ = true;
            return false;
        }
    }
    if (opt_.max_results != 0 && result_.count >= opt_.max_results) {
        stopped_ = true;
        return false;
    }
    return true;
}

// The options read into per-object and per-type flags: monic_, monic_t_, and the objects that
// must be bijective and the types whose variables are not bound.
void Engine::read_options(std::vector<char>& iso_ob, std::vector<char>& no_bind) {
    std::size_t nobs = s_.num_obs(), ntypes = s_.num_attr_types();
    monic_.assign(nobs, opt_.monic_all || opt_.iso ? 1 : 0);
    for (ObId ob : opt_.monic) {
        CATPLAN_ASSERT(ob.index() < nobs, "monic: object out of range");
        monic_[ob.index()] = 1;
    }
    iso_ob.assign(nobs, opt_.iso ? 1 : 0);
    for (ObId ob : opt_.iso_obs) {
        CATPLAN_ASSERT(ob.index() < nobs, "iso_obs: object out of range");
        iso_ob[ob.index()] = 1;
        monic_[ob.index()] = 1;
    }
    monic_t_.assign(ntypes, opt_.iso ? 1 : 0);
    for (AttrTypeId t : opt_.monic_attr_types) {
        CATPLAN_ASSERT(t.index() < ntypes, "monic_attr_types: type out of range");
        monic_t_[t.index()] = 1;
    }
    no_bind.assign(ntypes, 0);
    for (AttrTypeId t : opt_.no_bind) {
        CATPLAN_ASSERT(t.index() < ntypes, "no_bind: type out of range");
        no_bind[t.index()] = 1;
    }
}

// The variables of X that no attribute uses (floating_); false, with the error, when one of them
// could map to any value (infinitely many morphisms, reported before anything else as Catlab
// does).
bool Engine::find_floating(const std::vector<char>& no_bind) {
    std::size_t ntypes = s_.num_attr_types();
    std::vector<std::vector<char>> used(ntypes);
    for (std::size_t t = 0; t < ntypes; ++t) {
        used[t].assign(x_.num_vars(AttrTypeId(static_cast<std::uint32_t>(t))), 0);
    }
    for (std::uint32_t a = 0; a < s_.num_attrs(); ++a) {
        std::uint32_t t = s_.attr(AttrId(a)).codom.index();
        for (const Value& v : x_.column(AttrId(a))) {
            if (v.is_var()) {
                used[t][v.var_index()] = 1;
            }
        }
    }
    for (const VarBinding& b : opt_.initial_vars) {
        CATPLAN_ASSERT(b.type.index() < ntypes && b.var < used[b.type.index()].size(),
                       "initial_vars: variable out of range");
        used[b.type.index()][b.var] = 1;
    }
    for (std::uint32_t t = 0; t < ntypes; ++t) {
        for (std::uint32_t v = 0; v < used[t].size(); ++v) {
            if (used[t][v]) {
                continue;
            }
            if (!monic_t_[t] && !no_bind[t]) {
                result_.error = fmt::format(
                    "infinitely many homomorphisms: variable {} of attribute type {} is used by "
                    "no attribute, so it can map to any value; bind it with an initial binding, "
                    "or make {} monic or no_bind",
                    x_.value_label(AttrTypeId(t), Value::var(v)), s_.attr_type(AttrTypeId(t)).name,
                    s_.attr_type(AttrTypeId(t)).name);
                result_.complete = false;
                return false;
            }
            floating_.emplace_back(t, v);
        }
    }
    return true;
}

// Cardinality: an injective map needs room, a bijective one equal sizes.
bool Engine::room_for(const std::vector<char>& iso_ob) const {
    std::size_t nobs = s_.num_obs(), ntypes = s_.num_attr_types();
    for (std::uint32_t ob = 0; ob < nobs; ++ob) {
        std::size_t nx = x_.num_parts(ObId(ob)), ny = y_.num_parts(ObId(ob));
        if ((monic_[ob] && nx > ny) || (iso_ob[ob] && nx != ny)) {
            return false;
        }
    }
    for (std::uint32_t t = 0; t < ntypes; ++t) {
        std::size_t nx = x_.num_vars(AttrTypeId(t)), ny = y_.num_vars(AttrTypeId(t));
        if ((monic_t_[t] && nx > ny) || (opt_.iso && nx != ny)) {
            return false;
        }
    }
    return true;
}

// The search's tables, sized for X and Y.
void Engine::allocate() {
    std::size_t nobs = s_.num_obs(), ntypes = s_.num_attr_types();
    homs_out_.resize(nobs);
    for (std::uint32_t ob = 0; ob < nobs; ++ob) {
        homs_out_[ob].clear();
        for (HomId f : s_.homs_from(ObId(ob))) {
            homs_out_[ob].push_back(
                HomRef{s_.hom(f).codom.index(), x_.column(f).data(), y_.column(f).data()});
        }
    }
    assign_.resize(nobs);
    inv_.resize(nobs);
    dense_inv_.assign(nobs, 0);
    key_wanted_.assign(nobs, 0);
    cand_.resize(nobs);
    has_cand_.assign(nobs, 0);
    keys_.resize(nobs);
    for (std::uint32_t ob = 0; ob < nobs; ++ob) {
        cand_[ob].clear();
        keys_[ob].built = false;
    }
    trail_.clear();
    std::size_t total = 0;
    for (std::uint32_t ob = 0; ob < nobs; ++ob) {
        assign_[ob].assign(x_.num_parts(ObId(ob)), kNoPart);
        total += assign_[ob].size();
        unassigned_ += assign_[ob].size();
        // A dense inverse costs O(|Y|) to set up; when the pattern is small next to the state
        // (matching a rule in a large state), checking injectivity by a scan is cheaper.
        std::size_t nx = x_.num_parts(ObId(ob)), ny = y_.num_parts(ObId(ob));
        if (monic_[ob] && (nx > 16 || ny <= 64 * (nx + 1))) {
            dense_inv_[ob] = 1;
            inv_[ob].assign(ny, kNoPart);
        }
    }
    vbind_.resize(ntypes);
    vused_.resize(ntypes);
    for (std::uint32_t t = 0; t < ntypes; ++t) {
        vbind_[t].assign(x_.num_vars(AttrTypeId(t)), Value());
        total += vbind_[t].size();
        if (monic_t_[t]) {
            vused_[t].assign(y_.num_vars(AttrTypeId(t)), 0);
        }
    }
    trail_.reserve(total);
}

// The candidate sets of the options, intersected per part; false when one is empty.
bool Engine::restrict_candidates() {
    std::size_t nobs = s_.num_obs();
    bool empty_candidates = false;
    for (const CandidateSet& c : opt_.candidates) {
        std::uint32_t ob = c.ob.index();
        CATPLAN_ASSERT(ob < nobs && c.dom < x_.num_parts(c.ob), "candidates: part out of range");
        std::vector<Part> allowed = c.allowed;
        std::sort(allowed.begin(), allowed.end());
        allowed.erase(std::unique(allowed.begin(), allowed.end()), allowed.end());
        std::erase_if(allowed, [&](Part p) { return p >= y_.num_parts(c.ob); });
        if (cand_[ob].empty()) {
            cand_[ob].resize(x_.num_parts(c.ob));
        }
        auto& slot = cand_[ob][c.dom];
        if (has_cand_[ob] && !slot.empty()) {
            std::vector<Part> both;
            std::set_intersection(slot.begin(), slot.end(), allowed.begin(), allowed.end(),
                                  std::back_inserter(both));
            allowed = std::move(both);
        }
        has_cand_[ob] = 1;
        // An empty slot means "no restriction" in the engine, so an empty set ends the search.
        if (allowed.empty()) {
            empty_candidates = true;
        }
        slot = std::move(allowed);
    }
    return !empty_candidates;
}

// The initial bindings of variables and parts; false when they are inconsistent.
bool Engine::bind_initial() {
    std::size_t nobs = s_.num_obs();
    for (const VarBinding& b : opt_.initial_vars) {
        CATPLAN_ASSERT(!b.value.is_var() || b.value.var_index() < y_.num_vars(b.type),
                       "initial_vars: codomain variable out of range");
        if (!bind_var(b.type.index(), b.var, b.value)) {
            return false;
        }
    }
    for (const PartBinding& b : opt_.initial) {
        CATPLAN_ASSERT(b.ob.index() < nobs && b.dom < x_.num_parts(b.ob) &&
                           b.codom < y_.num_parts(b.ob),
                       "initial: part out of range");
        if (!assign(b.ob.index(), b.dom, b.codom)) {
            return false;
        }
    }
    return true;
}

bool Engine::prepare() {
    CATPLAN_ASSERT(searchable(x_, y_), "hom search between states on different schemas");
    std::vector<char> iso_ob, no_bind;
    floating_.clear();
    read_options(iso_ob, no_bind);
    if (!find_floating(no_bind) || !room_for(iso_ob)) {
        return false;
    }
    allocate();
    return restrict_candidates() && bind_initial();
}

HomSearchResult Engine::run() {
    if (prepare()) {
        search();
    }
    if (stopped_) {
        result_.complete = false;
    }
    return std::move(result_);
}

} // namespace

HomSearchResult run_search(const ACSet& x, const ACSet& y, const HomSearchOptions& options,
                           SearchMode mode, const std::function<bool(const ACSetMorphism&)>* fn) {
    Engine engine(x, y, options, mode, fn);
    return engine.run();
}

} // namespace catplan::hom::detail
