#include "catplan/schema/printer.hpp"

#include <fmt/format.h>

namespace catplan::schema {

std::string describe(const Schema& s) {
    std::string out = fmt::format("schema {}\n", s.name());
    out += fmt::format("  objects ({}):", s.num_obs());
    for (std::uint32_t i = 0; i < s.num_obs(); ++i) {
        out += fmt::format("{} {}", i ? "," : "", s.ob(ObId(i)).name);
    }
    out += fmt::format("\n  homs ({}):\n", s.num_homs());
    for (std::uint32_t i = 0; i < s.num_homs(); ++i) {
        const auto& h = s.hom(HomId(i));
        out += fmt::format("    {} : {} → {}\n", h.name, s.ob(h.dom).name, s.ob(h.codom).name);
    }
    out += fmt::format("  attribute types ({}):", s.num_attr_types());
    for (std::uint32_t i = 0; i < s.num_attr_types(); ++i) {
        const auto& t = s.attr_type(AttrTypeId(i));
        out += fmt::format("{} {} ({})", i ? "," : "", t.name, to_string(t.kind));
    }
    out += fmt::format("\n  attributes ({}):\n", s.num_attrs());
    for (std::uint32_t i = 0; i < s.num_attrs(); ++i) {
        const auto& a = s.attr(AttrId(i));
        out +=
            fmt::format("    {} : {} → {}\n", a.name, s.ob(a.dom).name, s.attr_type(a.codom).name);
    }
    if (!s.equations().empty()) {
        out += fmt::format("  equations ({}):\n", s.equations().size());
        for (const auto& eq : s.equations()) {
            out +=
                fmt::format("    {} == {}\n", s.path_to_string(eq.lhs), s.path_to_string(eq.rhs));
        }
    }
    return out;
}

} // namespace catplan::schema
