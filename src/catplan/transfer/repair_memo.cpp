#include "catplan/transfer/repair_memo.hpp"

#include "catplan/base/hash.hpp"

#include <algorithm>
#include <functional>
#include <numeric>

namespace catplan::transfer {
namespace {

using acset::ACSet;
using acset::Value;

// One thing a problem says about some names: a part of a pointed object, a hom value, an
// attribute value, a fact. `tag` says what, without the names; `args` are the names (their
// provisional numbers), in the order the tag places them.
struct Item {
    std::string tag;
    std::vector<std::uint32_t> args;
};

// Gathers the items of a problem, giving each name a provisional number as it comes.
class Items {
public:
    std::vector<Item> items;
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

    bool add(const ACSet& x, char side) {
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

private:
    static bool pointed(const schema::Schema& s, ObId ob) { return !s.homs_into(ob).empty(); }

    // "Pi3": what an item is (a part, hom, attribute or fact), on which side, of which object.
    static std::string tag(char what, char side, std::uint32_t index) {
        std::string t{what, side};
        t += std::to_string(index);
        return t;
    }

    std::optional<std::uint32_t> name_of(const ACSet& x, ObId ob, Part p) const {
        auto it = number.find(x.part_name(ob, p));
        return it == number.end() ? std::nullopt : std::optional<std::uint32_t>(it->second);
    }

    // A value: a name's number (a string that is a name, as PDDL's object names are), else the
    // value itself.
    void value(Item& item, const Value& v) const {
        if (v.tag() == Value::Tag::String) {
            auto it = number.find(v.as_string());
            if (it != number.end()) {
                item.tag += "=@";
                item.args.push_back(it->second);
                return;
            }
        }
        item.tag += "=" + v.to_string();
    }

    bool add_part(const ACSet& x, char side, ObId ob, Part p) {
        const auto& s = x.schema();
        auto self = name_of(x, ob, p);
        if (!self) {
            return false;
        }
        items.push_back({tag('P', side, ob.index()), {*self}});
        for (HomId f : s.homs_from(ob)) {
            Part t = x.subpart(f, p);
            if (t == kNoPart) {
                continue;
            }
            auto target = name_of(x, s.hom(f).codom, t);
            if (!target) {
                return false;
            }
            items.push_back({tag('H', side, f.index()), {*self, *target}});
        }
        for (AttrId a : s.attrs_from(ob)) {
            const Value& v = x.subpart(a, p);
            if (!v.is_unset()) {
                Item item{tag('A', side, a.index()), {*self}};
                value(item, v);
                items.push_back(std::move(item));
            }
        }
        return true;
    }

    bool add_fact(const ACSet& x, char side, ObId ob, Part p) {
        const auto& s = x.schema();
        Item item{tag('F', side, ob.index()), {}};
        for (HomId f : s.homs_from(ob)) {
            Part t = x.subpart(f, p);
            if (t == kNoPart) {
                item.tag += "_";
                continue;
            }
            auto target = name_of(x, s.hom(f).codom, t);
            if (!target) {
                return false;
            }
            item.tag += "#";
            item.args.push_back(*target);
        }
        for (AttrId a : s.attrs_from(ob)) {
            value(item, x.subpart(a, p));
        }
        items.push_back(std::move(item));
        return true;
    }
};

// Colour refinement: each name's colour from the items it is in, the place it has there and the
// colours of the other names there, a few rounds; then the names in the order of their colours
// (ties in the order they came).
std::vector<std::uint32_t> canonical_order(const Items& in) {
    std::size_t n = in.names.size();
    std::vector<std::uint64_t> colour(n, 0);
    std::vector<std::uint64_t> tags;
    for (const auto& item : in.items) {
        tags.push_back(std::hash<std::string>()(item.tag));
    }
    std::vector<std::vector<std::uint64_t>> seen(n);
    for (int round = 0; round < 3; ++round) {
        for (auto& v : seen) {
            v.clear();
        }
        for (std::size_t i = 0; i < in.items.size(); ++i) {
            const auto& args = in.items[i].args;
            for (std::size_t k = 0; k < args.size(); ++k) {
                std::uint64_t h = hash_combine(tags[i], k);
                for (std::uint32_t a : args) {
                    h = hash_combine(h, colour[a]);
                }
                seen[args[k]].push_back(h);
            }
        }
        for (std::size_t a = 0; a < n; ++a) {
            std::sort(seen[a].begin(), seen[a].end());
            std::uint64_t h = hash_mix(colour[a]);
            for (std::uint64_t x : seen[a]) {
                h = hash_combine(h, x);
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

} // namespace

std::optional<RepairShape> repair_shape(const ACSet& initial, const ACSet& goal) {
    Items in;
    if (!in.add_names(initial) || !in.add(initial, 'i') || !in.add(goal, 'g')) {
        return std::nullopt;
    }
    auto order = canonical_order(in);
    std::vector<std::uint32_t> number(order.size());
    RepairShape out;
    for (std::uint32_t k = 0; k < order.size(); ++k) {
        number[order[k]] = k;
        out.names.push_back(in.names[order[k]]);
        out.number.emplace(in.names[order[k]], k);
    }
    std::vector<std::string> lines;
    lines.reserve(in.items.size());
    for (const auto& item : in.items) {
        std::string line = item.tag;
        for (std::uint32_t a : item.args) {
            line += ' ';
            line += std::to_string(number[a]);
        }
        lines.push_back(std::move(line));
    }
    std::sort(lines.begin(), lines.end());
    out.key = std::to_string(order.size());
    for (const auto& line : lines) {
        out.key += '\n';
        out.key += line;
    }
    return out;
}

const RepairMemo::Entry* RepairMemo::find(const RepairShape& shape) const {
    auto it = entries_.find(shape.key);
    return it == entries_.end() ? nullptr : &it->second;
}

void RepairMemo::remember(const RepairShape& shape, const std::vector<plan::Step>& steps,
                          std::size_t origin) {
    Entry e;
    e.solved = true;
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
