#include "catplan/transfer/rename.hpp"

#include "catplan/base/ascii.hpp"

#include <cctype>
#include <fmt/format.h>
#include <map>
#include <vector>

namespace catplan::transfer {
namespace {

using acset::ACSet;

// "BreadSliced" -> "bread", "Knife" -> "knife", "on_table" -> "on_table".
std::string first_word(std::string_view ob_name) {
    std::string out;
    for (std::size_t i = 0; i < ob_name.size(); ++i) {
        auto c = static_cast<unsigned char>(ob_name[i]);
        if (i > 0 && std::isupper(c)) {
            break;
        }
        out.push_back(ascii_lower(static_cast<char>(c)));
    }
    return out.empty() ? std::string(ob_name) : out;
}

// How many is-a homs leave the part named `name` of ob for a part of the same name.
int is_a_homs(const ACSet& y, ObId ob, Part p, std::string_view name) {
    int n = 0;
    for (HomId f : y.schema().homs_from(ob)) {
        Part q = y.subpart(f, p);
        if (q != kNoPart && y.part_name(y.schema().hom(f).codom, q) == name) {
            ++n;
        }
    }
    return n;
}

} // namespace

Renaming names_by_type(const ACSet& y) {
    const auto& s = y.schema();

    // name -> (ob, part) of its most specific holder so far, in order of first appearance.
    struct Holder {
        ObId ob;
        Part p;
        int is_a;
    };

    std::vector<std::string> order;
    std::map<std::string, Holder, std::less<>> best;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        for (Part p = 0; p < y.num_parts(ob); ++p) {
            std::string name(y.part_name(ob, p));
            // Generated names (#7 for an unnamed part, block@3 for a created one) stay.
            if (name.empty() || name[0] == '#' || name.find('@') != std::string::npos) {
                continue;
            }
            Holder h{ob, p, is_a_homs(y, ob, p, name)};
            auto it = best.find(name);
            if (it == best.end()) {
                order.push_back(name);
                best.emplace(name, h);
                continue;
            }
            const Holder& b = it->second;
            bool better =
                h.is_a > b.is_a || (h.is_a == b.is_a && y.num_parts(h.ob) < y.num_parts(b.ob));
            if (better) {
                it->second = h;
            }
        }
    }
    // Number per type in the order of the holders' parts.
    std::map<std::pair<std::uint32_t, Part>, std::string> by_part;
    for (const auto& name : order) {
        const Holder& h = best.at(name);
        by_part.emplace(std::pair{h.ob.index(), h.p}, name);
    }
    std::map<std::string, int, std::less<>> counters;
    Renaming out;
    for (const auto& [key, name] : by_part) {
        // A subtype (BreadSliced, with is-a homs) is called by its first word, others in full.
        const std::string& ob_name = s.ob(ObId(key.first)).name;
        std::string base = best.at(name).is_a > 0 ? first_word(ob_name) : ascii_lowercase(ob_name);
        out.emplace(name, fmt::format("{}{}", base, ++counters[base]));
    }
    return out;
}

void rename_parts(ACSet& y, const Renaming& renaming) {
    if (renaming.empty()) {
        return; // no renaming (the transfer's default): each step's state is left as it is
    }
    for (std::uint32_t o = 0; o < y.schema().num_obs(); ++o) {
        for (Part p = 0; p < y.num_parts(ObId(o)); ++p) {
            auto it = renaming.find(std::string(y.part_name(ObId(o), p)));
            if (it != renaming.end()) {
                y.set_part_name(ObId(o), p, it->second);
            }
        }
    }
}

std::string renamed(const Renaming& renaming, std::string_view name) {
    auto it = renaming.find(std::string(name));
    return it == renaming.end() ? std::string(name) : it->second;
}

} // namespace catplan::transfer
