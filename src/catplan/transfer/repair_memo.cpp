#include "catplan/transfer/repair_memo.hpp"

#include "catplan/base/hash.hpp"
#include "catplan/base/symbol.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <span>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using acset::Value;

// The words of an item's code: what it is, then per hom of a fact whether it is set, per
// attribute whether its value is a name (its number is then an argument) or which value.
enum Word : std::uint32_t {
    kPart,
    kHom,
    kAttr,
    kFact,
    kUnsetHom,
    kSetHom,
    kNameValue,
    kValue,
    kFunctionValue
};

// The things a problem says about some names: a part of a pointed object, a hom value, an
// attribute value, a fact. An item's code says what, without the names (kinds and indices as
// numbers, other values as the symbols of their texts); its arguments are the names (their
// provisional numbers), in the order the code places them. Every item's words are kept in two
// flat arrays, as ranges.
class Items {
public:
    struct Item {
        std::uint32_t code = 0, code_end = 0; ///< its range of `codes`
        std::uint32_t args = 0, args_end = 0; ///< its range of `arguments`
    };

    std::vector<Item> items;
    std::vector<std::uint32_t> codes, arguments;
    std::vector<std::string_view> names;
    std::unordered_map<std::string_view, std::uint32_t> number;

    // The parts of pointed objects of the initial state, which name every part the goal names.
    bool add_names(const ACSet& x) {
        const auto& s = x.schema();
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            ObId ob(o);
            for (Part p = 0; pointed(s, ob) && p < x.num_parts(ob); ++p) {
                std::string_view n = x.part_name(ob, p);
                if (n.empty()) {
                    return false;
                }
                if (number.emplace(n, static_cast<std::uint32_t>(names.size())).second) {
                    names.push_back(n);
                }
            }
        }
        return true;
    }

    bool add(const ACSet& x, std::uint32_t side) {
        const auto& s = x.schema();
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            ObId ob(o);
            for (Part p = 0; p < x.num_parts(ob); ++p) {
                if (!(pointed(s, ob) ? add_part(x, side, ob, p) : add_fact(x, side, ob, p))) {
                    return false;
                }
            }
        }
        return true;
    }

    // The function values that take some of the names and that a step on the names can read:
    // per value, its function and value as code, then per argument a name's number, or a part a
    // cost reads by name as itself.
    void add_values(const ValueIndex& index) {
        std::vector<std::uint32_t> taken;
        for (std::string_view n : names) {
            auto of = index.of(n);
            taken.insert(taken.end(), of.begin(), of.end());
        }
        std::sort(taken.begin(), taken.end());
        taken.erase(std::unique(taken.begin(), taken.end()), taken.end());
        for (std::uint32_t i : taken) {
            const auto& e = index.entries()[i];
            bool readable = std::all_of(e.args.begin(), e.args.end(), [&](const auto& a) {
                return index.read_by_name(a) || number.contains(a);
            });
            if (!readable) {
                continue; // an argument outside the focus, which no step here can take
            }
            auto bits = static_cast<std::uint64_t>(e.value);
            // The second word is a side, as every code's is; values are said of neither.
            start({kFunctionValue, 0, e.function.id(), static_cast<std::uint32_t>(bits),
                   static_cast<std::uint32_t>(bits >> 32U)});
            for (const auto& a : e.args) {
                if (index.read_by_name(a)) {
                    codes.push_back(kValue);
                    codes.push_back(Symbol::intern(a).id());
                } else {
                    codes.push_back(kNameValue);
                    arguments.push_back(number.at(a));
                }
            }
            finish();
        }
    }

    std::span<const std::uint32_t> code(const Item& i) const {
        return std::span(codes).subspan(i.code, i.code_end - i.code);
    }

    std::span<const std::uint32_t> args(const Item& i) const {
        return std::span(arguments).subspan(i.args, i.args_end - i.args);
    }

private:
    static bool pointed(const schema::Schema& s, ObId ob) { return !s.homs_into(ob).empty(); }

    std::optional<std::uint32_t> name_of(const ACSet& x, ObId ob, Part p) const {
        auto it = number.find(x.part_name(ob, p));
        return it == number.end() ? std::nullopt : std::optional<std::uint32_t>(it->second);
    }

    // Starts an item whose code begins with these words.
    void start(std::initializer_list<std::uint32_t> words) {
        auto c = static_cast<std::uint32_t>(codes.size());
        auto a = static_cast<std::uint32_t>(arguments.size());
        codes.insert(codes.end(), words);
        items.push_back({c, c, a, a});
    }

    // Ends the item started last.
    void finish() {
        items.back().code_end = static_cast<std::uint32_t>(codes.size());
        items.back().args_end = static_cast<std::uint32_t>(arguments.size());
    }

    // A value: a name's number (a string that is a name, as PDDL's object names are), else the
    // value itself, by the symbol of its text.
    void value(const Value& v) {
        if (v.tag() == Value::Tag::String) {
            auto it = number.find(v.as_string());
            if (it != number.end()) {
                codes.push_back(kNameValue);
                arguments.push_back(it->second);
                return;
            }
        }
        codes.push_back(kValue);
        codes.push_back(Symbol::intern(v.to_string()).id());
    }

    bool add_part(const ACSet& x, std::uint32_t side, ObId ob, Part p) {
        const auto& s = x.schema();
        auto self = name_of(x, ob, p);
        if (!self) {
            return false;
        }
        start({kPart, side, ob.index()});
        arguments.push_back(*self);
        finish();
        for (HomId f : s.homs_from(ob)) {
            Part t = x.subpart(f, p);
            if (t == kNoPart) {
                continue;
            }
            auto target = name_of(x, s.hom(f).codom, t);
            if (!target) {
                return false;
            }
            start({kHom, side, f.index()});
            arguments.push_back(*self);
            arguments.push_back(*target);
            finish();
        }
        for (AttrId a : s.attrs_from(ob)) {
            const Value& v = x.subpart(a, p);
            if (!v.is_unset()) {
                start({kAttr, side, a.index()});
                arguments.push_back(*self);
                value(v);
                finish();
            }
        }
        return true;
    }

    bool add_fact(const ACSet& x, std::uint32_t side, ObId ob, Part p) {
        const auto& s = x.schema();
        start({kFact, side, ob.index()});
        for (HomId f : s.homs_from(ob)) {
            Part t = x.subpart(f, p);
            if (t == kNoPart) {
                codes.push_back(kUnsetHom);
                continue;
            }
            auto target = name_of(x, s.hom(f).codom, t);
            if (!target) {
                return false;
            }
            codes.push_back(kSetHom);
            arguments.push_back(*target);
        }
        for (AttrId a : s.attrs_from(ob)) {
            value(x.subpart(a, p));
        }
        finish();
        return true;
    }
};

std::uint64_t hash_words(std::span<const std::uint32_t> words) {
    std::uint64_t h = hash_mix(words.size());
    for (std::uint32_t w : words) {
        h = hash_combine(h, w);
    }
    return h;
}

// Colour refinement: each name's colour from the items it is in, the place it has there and the
// colours of the other names there, a few rounds; then the names in the order of their colours
// (ties in the order they came).
std::vector<std::uint32_t> canonical_order(const Items& in) {
    std::size_t n = in.names.size();
    std::vector<std::uint64_t> colour(n, 0);
    std::vector<std::uint64_t> tags;
    tags.reserve(in.items.size());
    for (const auto& item : in.items) {
        tags.push_back(hash_words(in.code(item)));
    }
    // Per name, the hashes of the places it has, gathered as (name, hash) pairs and sorted.
    std::vector<std::pair<std::uint32_t, std::uint64_t>> seen;
    seen.reserve(in.arguments.size());
    for (int round = 0; round < 3; ++round) {
        seen.clear();
        for (std::size_t i = 0; i < in.items.size(); ++i) {
            auto args = in.args(in.items[i]);
            for (std::size_t k = 0; k < args.size(); ++k) {
                std::uint64_t h = hash_combine(tags[i], k);
                for (std::uint32_t a : args) {
                    h = hash_combine(h, colour[a]);
                }
                seen.emplace_back(args[k], h);
            }
        }
        std::sort(seen.begin(), seen.end());
        for (std::size_t a = 0, j = 0; a < n; ++a) {
            std::uint64_t h = hash_mix(colour[a]);
            for (; j < seen.size() && seen[j].first == a; ++j) {
                h = hash_combine(h, seen[j].second);
            }
            colour[a] = h;
        }
    }
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return colour[a] < colour[b]; });
    return order;
}

// Whether item a's line (its code, then its arguments' final numbers) sorts before b's.
bool line_less(const Items& in, const std::vector<std::uint32_t>& number, const Items::Item& a,
               const Items::Item& b) {
    auto ca = in.code(a), cb = in.code(b);
    if (ca.size() != cb.size()) {
        return ca.size() < cb.size();
    }
    if (!std::equal(ca.begin(), ca.end(), cb.begin())) {
        return std::lexicographical_compare(ca.begin(), ca.end(), cb.begin(), cb.end());
    }
    auto aa = in.args(a), ab = in.args(b);
    return std::lexicographical_compare(
        aa.begin(), aa.end(), ab.begin(), ab.end(),
        [&](std::uint32_t x, std::uint32_t y) { return number[x] < number[y]; });
}

// The shape of the items `in` holds: the names numbered by canonical_order, and the items as a
// set, whatever order they came in (their lines sorted, each after the length of its code, which
// fixes the number of its arguments).
RepairShape shape_of(Items& in) {
    auto order = canonical_order(in);
    std::vector<std::uint32_t> number(order.size());
    RepairShape out;
    out.names.reserve(order.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) {
        number[order[k]] = k;
        out.names.push_back(in.names[order[k]]);
        out.number.emplace(in.names[order[k]], k);
    }
    std::sort(in.items.begin(), in.items.end(),
              [&](const auto& a, const auto& b) { return line_less(in, number, a, b); });
    out.key.reserve(1 + in.items.size() + in.codes.size() + in.arguments.size());
    out.key.push_back(static_cast<std::uint32_t>(order.size()));
    for (const auto& item : in.items) {
        auto code = in.code(item);
        out.key.push_back(static_cast<std::uint32_t>(code.size()));
        out.key.insert(out.key.end(), code.begin(), code.end());
        for (std::uint32_t a : in.args(item)) {
            out.key.push_back(number[a]);
        }
    }
    return out;
}

// An item's line without its side (every code's second word): what it says of which names.
std::vector<std::uint32_t> unsided_line(const Items& in, const Items::Item& item) {
    auto code = in.code(item);
    auto args = in.args(item);
    // The code's length first, as in a shape's key: it fixes where the arguments start.
    std::vector<std::uint32_t> w{static_cast<std::uint32_t>(code.size()), code[0]};
    w.insert(w.end(), code.begin() + 2, code.end());
    w.insert(w.end(), args.begin(), args.end());
    return w;
}

// Which items are frame: said alike of the initial state and of the goal, paired off one to one.
std::vector<char> frame_items(const Items& in) {
    std::vector<std::pair<std::vector<std::uint32_t>, std::uint32_t>> lines; // (line, item)
    lines.reserve(in.items.size());
    for (std::uint32_t i = 0; i < in.items.size(); ++i) {
        lines.emplace_back(unsided_line(in, in.items[i]), i);
    }
    std::sort(lines.begin(), lines.end());
    std::vector<char> frame(in.items.size(), 0);
    for (std::size_t k = 0; k < lines.size();) {
        std::size_t end = k;
        std::vector<std::uint32_t> sides[2];
        for (; end < lines.size() && lines[end].first == lines[k].first; ++end) {
            auto i = lines[end].second;
            sides[in.code(in.items[i])[1]].push_back(i);
        }
        for (std::size_t j = 0; j < std::min(sides[0].size(), sides[1].size()); ++j) {
            frame[sides[0][j]] = frame[sides[1][j]] = 1;
        }
        k = end;
    }
    return frame;
}

// The items of `in` that are not frame (what the repair changes), with the names they mention,
// numbered anew in the order they come.
Items change_of(const Items& in) {
    auto frame = frame_items(in);
    Items out;
    constexpr auto kUnnumbered = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> renumber(in.names.size(), kUnnumbered);
    for (std::size_t i = 0; i < in.items.size(); ++i) {
        if (frame[i]) {
            continue;
        }
        const auto& item = in.items[i];
        auto c = static_cast<std::uint32_t>(out.codes.size());
        auto a = static_cast<std::uint32_t>(out.arguments.size());
        auto code = in.code(item);
        out.codes.insert(out.codes.end(), code.begin(), code.end());
        for (std::uint32_t n : in.args(item)) {
            if (renumber[n] == kUnnumbered) {
                renumber[n] = static_cast<std::uint32_t>(out.names.size());
                out.names.push_back(in.names[n]);
                out.number.emplace(in.names[n], renumber[n]);
            }
            out.arguments.push_back(renumber[n]);
        }
        out.items.push_back({c, static_cast<std::uint32_t>(out.codes.size()), a,
                             static_cast<std::uint32_t>(out.arguments.size())});
    }
    return out;
}

// The items of a repair's problem, or nullopt when a part that homs point into has no name (or
// a goal part no namesake in the initial state).
std::optional<Items> items_of(const ACSet& initial, const ACSet& goal) {
    Items in;
    if (!in.add_names(initial) || !in.add(initial, 0) || !in.add(goal, 1)) {
        return std::nullopt;
    }
    return in;
}

} // namespace

std::size_t RepairShape::KeyHash::operator()(const std::vector<std::uint32_t>& words) const {
    return hash_words(words);
}

ValueIndex::ValueIndex(const std::vector<plan::FunctionValue>& values, const plan::Domain& domain) {
    for (const auto& rule : domain.rules) {
        if (!rule->cost) {
            continue;
        }
        for (const auto& term : rule->cost->terms) {
            for (const auto& a : term.arguments) {
                if (a.parameter < 0 && !a.constant.empty()) {
                    by_name_read_.insert(a.constant);
                }
            }
        }
    }
    entries_.reserve(values.size());
    for (const auto& v : values) {
        entries_.push_back({Symbol::intern(v.function), v.args, v.value});
    }
    // The keys view the entries' strings, which stay put: entries_ is not grown again.
    for (std::uint32_t i = 0; i < entries_.size(); ++i) {
        for (const auto& a : entries_[i].args) {
            auto& list = by_name_[a];
            if (list.empty() || list.back() != i) {
                list.push_back(i);
            }
        }
    }
}

std::span<const std::uint32_t> ValueIndex::of(std::string_view name) const {
    auto it = by_name_.find(name);
    return it == by_name_.end() ? std::span<const std::uint32_t>() : std::span(it->second);
}

std::optional<RepairShape> repair_shape(const ACSet& initial, const ACSet& goal,
                                        const ValueIndex* values) {
    auto in = items_of(initial, goal);
    if (in && values != nullptr) {
        in->add_values(*values);
    }
    return in ? std::optional(shape_of(*in)) : std::nullopt;
}

std::optional<RepairShape> change_shape(const ACSet& initial, const ACSet& goal) {
    auto in = items_of(initial, goal);
    if (!in) {
        return std::nullopt;
    }
    auto change = change_of(*in);
    return shape_of(change);
}

const RepairMemo::Entry* RepairMemo::find(const RepairShape& shape) const {
    auto it = entries_.find(shape.key);
    return it == entries_.end() ? nullptr : &it->second;
}

void RepairMemo::remember(const RepairShape& shape, const std::vector<plan::Step>& steps,
                          std::size_t origin, bool least_cost) {
    Entry e;
    e.solved = true;
    e.least_cost = least_cost;
    e.origin = origin;
    for (const auto& step : steps) {
        e.actions.push_back(step.action);
        auto& args = e.args.emplace_back();
        for (const auto& a : step.args) {
            auto it = shape.number.find(a);
            if (it == shape.number.end()) {
                return;
            }
            args.push_back(it->second);
        }
    }
    entries_.emplace(shape.key, std::move(e));
}

void RepairMemo::remember_failure(const RepairShape& shape, std::size_t origin) {
    Entry e;
    e.origin = origin;
    entries_.emplace(shape.key, std::move(e));
}

std::vector<plan::Step> RepairMemo::renamed(const Entry& e, const RepairShape& shape) {
    std::vector<plan::Step> out;
    for (std::size_t i = 0; i < e.actions.size(); ++i) {
        plan::Step step;
        step.action = e.actions[i];
        for (std::uint32_t a : e.args[i]) {
            step.args.emplace_back(shape.names[a]);
        }
        out.push_back(std::move(step));
    }
    return out;
}

} // namespace catplan::transfer
