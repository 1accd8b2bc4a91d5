#include "catplan/transfer/terms.hpp"

#include "catplan/plan/validate.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tuple>

namespace catplan::transfer {

bool is_user_name(std::string_view name) {
    return !name.empty() && name.find_first_of("#@(") == std::string_view::npos;
}

std::optional<std::string> tuple_term(const acset::ACSet& x, ObId ob, Part p) {
    const auto& s = x.schema();
    const auto& homs = s.homs_from(ob);
    if (homs.empty() || !s.homs_into(ob).empty() || !s.attrs_from(ob).empty()) {
        return std::nullopt;
    }
    std::vector<std::string> args;
    for (HomId f : homs) {
        Part q = x.subpart(f, p);
        if (q == kNoPart) {
            return std::nullopt;
        }
        // Nothing points at ob, so no part of the tuple is a tuple itself: this recursion stops.
        args.push_back(part_word(x, s.hom(f).codom, q));
    }
    return fmt::format("{}({})", s.ob(ob).name, fmt::join(args, ", "));
}

namespace {

using Reach = std::tuple<std::uint32_t, Part, std::uint32_t>;

// (object, part, hom) of each named part that reaches p in one hom, in order.
std::vector<Reach> named_reaches(const acset::ACSet& x, ObId ob, Part p) {
    const auto& s = x.schema();
    std::vector<Reach> from;
    for (HomId f : s.homs_into(ob)) {
        ObId d = s.hom(f).dom;
        for (Part q : x.incident(f, p)) {
            if (is_user_name(x.part_name(d, q))) {
                from.emplace_back(d.index(), q, f.index());
            }
        }
    }
    std::sort(from.begin(), from.end());
    return from;
}

std::string reach_word(const acset::ACSet& x, const Reach& r) {
    auto [d, q, f] = r;
    return fmt::format("{}({})", x.schema().hom(HomId(f)).name, x.part_name(ObId(d), q));
}

// A part's words in order (its name; hom(name) for each named part reaching it; its tuple term;
// its label), or only the first of them.
std::vector<std::string> words_of(const acset::ACSet& x, ObId ob, Part p, bool first_only) {
    std::vector<std::string> words;
    std::string_view name = x.part_name(ob, p);
    if (is_user_name(name)) {
        words.emplace_back(name);
        return words;
    }
    for (const auto& r : named_reaches(x, ob, p)) {
        words.push_back(reach_word(x, r));
        if (first_only) {
            return words;
        }
    }
    if (auto t = tuple_term(x, ob, p)) {
        words.push_back(std::move(*t));
        if (first_only) {
            return words;
        }
    }
    words.push_back(x.part_label(ob, p));
    return words;
}

} // namespace

std::vector<std::string> part_words(const acset::ACSet& x, ObId ob, Part p) {
    return words_of(x, ob, p, false);
}

bool has_readable_word(const acset::ACSet& x, ObId ob, Part p) {
    auto words = part_words(x, ob, p);
    return words.size() > 1 || is_user_name(words.front());
}

std::string part_word(const acset::ACSet& x, ObId ob, Part p) {
    if (p == kNoPart) {
        return "_";
    }
    return std::move(words_of(x, ob, p, true).front());
}

namespace {

// The first word other than `avoid`.
const std::string& word_other_than(const std::vector<std::string>& words, std::string_view avoid) {
    for (const auto& w : words) {
        if (w != avoid) {
            return w;
        }
    }
    return words.back();
}

} // namespace

std::string part_statement(const acset::ACSet& x, ObId ob, Part p) {
    return fmt::format("{} {}", x.schema().ob(ob).name, part_word(x, ob, p));
}

std::string hom_statement(const acset::ACSet& x, HomId f, Part p) {
    const auto& h = x.schema().hom(f);
    std::string term = fmt::format("{}({})", h.name, part_word(x, h.dom, p));
    Part q = x.subpart(f, p);
    if (q == kNoPart) {
        return term + " == _";
    }
    return fmt::format("{} == {}", term, word_other_than(part_words(x, h.codom, q), term));
}

std::string attr_statement(const acset::ACSet& x, AttrId a, Part p) {
    const auto& at = x.schema().attr(a);
    const auto& v = x.subpart(a, p);
    return fmt::format("{}({}) == {}", at.name, part_word(x, at.dom, p),
                       v.is_concrete() ? v.to_string() : std::string("?"));
}

std::vector<std::string> part_statements(const acset::ACSet& x, ObId ob, Part p) {
    const auto& s = x.schema();
    if (!is_user_name(x.part_name(ob, p))) {
        if (auto t = tuple_term(x, ob, p)) {
            return {std::move(*t)}; // clear(a) says all that `clear #1, clear_1(#1) == a` says
        }
    }
    std::vector<std::string> out{part_statement(x, ob, p)};
    for (HomId f : s.homs_from(ob)) {
        if (x.subpart(f, p) != kNoPart) {
            out.push_back(hom_statement(x, f, p));
        }
    }
    for (AttrId a : s.attrs_from(ob)) {
        if (!x.subpart(a, p).is_unset()) {
            out.push_back(attr_statement(x, a, p));
        }
    }
    return out;
}

std::string describe_bindings(const hom::ACSetMorphism& m, const acset::ACSet& l,
                              const acset::ACSet& x, const LOrigins* origins) {
    plan::MatchWords words;
    words.part = [](const acset::ACSet& y, ObId ob, Part p) { return part_word(y, ob, p); };
    if (origins != nullptr) {
        words.group = [origins](ObId ob, Part p) -> std::optional<std::uint64_t> {
            const auto& o = (*origins)[ob.index()];
            if (!o || p >= o->parts.size()) {
                return std::nullopt;
            }
            return (std::uint64_t{o->ob.index()} << 32) | o->parts[p];
        };
    }
    return plan::describe_match(m, l, x, words);
}

} // namespace catplan::transfer
