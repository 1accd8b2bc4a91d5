#pragma once
// Test helpers of the db layer: seeded random states on any schema, exact comparison (names and
// variables included), and the examples' declarations.

#include "catplan/acset/acset.hpp"
#include "catplan/base/diagnostic.hpp"
#include "catplan/lang/module.hpp"

#include <random>
#include <string>
#include <vector>

namespace catplan::db::testing {

using acset::ACSet;
using acset::Value;

/// A random state on s: up to max_parts parts per object, homs unset with probability 1/8
/// (when `partial`), attribute values from a few per kind or one of a few variables, about half
/// the parts named (names may repeat, as they may in catplan).
inline ACSet random_state(const schema::SchemaPtr& s, std::mt19937_64& rng, std::size_t max_parts,
                          bool partial = true) {
    ACSet x(s);
    auto pick = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
    };
    for (std::uint32_t t = 0; t < s->num_attr_types(); ++t) {
        std::size_t n = pick(3);
        for (std::size_t j = 0; j < n; ++j) {
            x.add_var(AttrTypeId(t), pick(2) == 0 ? "" : "v" + std::to_string(j));
        }
    }
    for (std::uint32_t o = 0; o < s->num_obs(); ++o) {
        std::size_t n = pick(max_parts + 1);
        for (std::size_t i = 0; i < n; ++i) {
            std::string name =
                pick(2) == 0 ? "" : s->ob(ObId(o)).name + std::to_string(pick(n + 2));
            x.add_part(ObId(o), name);
        }
    }
    static const char* const kWords[] = {"red", "purple", "it's", "a\tb", "", "blue"};
    for (std::uint32_t h = 0; h < s->num_homs(); ++h) {
        const auto& info = s->hom(HomId(h));
        std::size_t m = x.num_parts(info.codom);
        for (Part p = 0; p < x.num_parts(info.dom); ++p) {
            if (m > 0 && (!partial || pick(8) != 0)) {
                x.set_subpart(HomId(h), p, static_cast<Part>(pick(m)));
            }
        }
    }
    for (std::uint32_t a = 0; a < s->num_attrs(); ++a) {
        const auto& info = s->attr(AttrId(a));
        std::size_t vars = x.num_vars(info.codom);
        for (Part p = 0; p < x.num_parts(info.dom); ++p) {
            std::size_t r = pick(10);
            Value v;
            if (r < 2 && vars > 0) {
                v = Value::var(static_cast<std::uint32_t>(pick(vars)));
            } else if (r == 2 && partial) {
                continue; // unset
            } else {
                switch (s->attr_type(info.codom).kind) {
                case schema::ValueKind::Bool:
                    v = Value::boolean(pick(2) == 1);
                    break;
                case schema::ValueKind::Int:
                    v = Value::integer(static_cast<std::int64_t>(pick(5)) - 2);
                    break;
                case schema::ValueKind::Float:
                    v = Value::real(0.1 * static_cast<double>(pick(5)) - 0.2);
                    break;
                case schema::ValueKind::String:
                    v = Value::string(kWords[pick(6)]);
                    break;
                default:
                    continue;
                }
            }
            x.set_subpart(AttrId(a), p, v);
        }
    }
    return x;
}

/// Equal parts, columns, variables, and the same names of parts and variables.
inline bool same_state(const ACSet& a, const ACSet& b, std::string* why = nullptr) {
    auto say = [&](std::string w) {
        if (why != nullptr) {
            *why = std::move(w);
        }
        return false;
    };
    const auto& s = a.schema();
    if (!(a == b)) {
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            if (a.num_parts(ObId(o)) != b.num_parts(ObId(o))) {
                return say(s.ob(ObId(o)).name + " has " + std::to_string(a.num_parts(ObId(o))) +
                           " and " + std::to_string(b.num_parts(ObId(o))) + " parts");
            }
        }
        for (std::uint32_t h = 0; h < s.num_homs(); ++h) {
            for (Part p = 0; p < a.num_parts(s.hom(HomId(h)).dom); ++p) {
                if (a.subpart(HomId(h), p) != b.subpart(HomId(h), p)) {
                    return say(s.hom(HomId(h)).name + "(" + std::to_string(p + 1) + ") differs");
                }
            }
        }
        for (std::uint32_t at = 0; at < s.num_attrs(); ++at) {
            for (Part p = 0; p < a.num_parts(s.attr(AttrId(at)).dom); ++p) {
                if (!(a.subpart(AttrId(at), p) == b.subpart(AttrId(at), p))) {
                    return say(s.attr(AttrId(at)).name + "(" + std::to_string(p + 1) + ") is " +
                               a.subpart(AttrId(at), p).to_string() + " and " +
                               b.subpart(AttrId(at), p).to_string());
                }
            }
        }
        return say("the states differ in their variables");
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < a.num_parts(ObId(o)); ++p) {
            if (a.part_name(ObId(o), p) != b.part_name(ObId(o), p)) {
                return say("part " + std::to_string(p + 1) + " of " + s.ob(ObId(o)).name +
                           " is named '" + std::string(a.part_name(ObId(o), p)) + "' and '" +
                           std::string(b.part_name(ObId(o), p)) + "'");
            }
        }
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        for (std::uint32_t j = 0; j < a.num_vars(AttrTypeId(t)); ++j) {
            if (a.var_name(AttrTypeId(t), j) != b.var_name(AttrTypeId(t), j)) {
                return say("variable " + std::to_string(j + 1) + " of " +
                           s.attr_type(AttrTypeId(t)).name + " is named differently");
            }
        }
    }
    return true;
}

/// The example files of the repository that declare something.
inline std::vector<std::string> example_files() {
    return {"examples/colorblocksworld/colorblocksworld.cp",
            "examples/colorblocks_to_kitchen/appendix_map.cp",
            "examples/kitchenworld/kitchenworld.cp",
            "examples/sandwich_kitchen/sandwich_kitchen.cp",
            "examples/hanoi/hanoi.cp",
            "examples/warehouse/warehouse.cp",
            "examples/kitchen_to_warehouse/kitchen_to_warehouse.cp"};
}

/// Loads a file of the repository (asserting that it has no errors).
inline lang::Module load_example(const std::string& file, SourceManager& sources) {
    DiagnosticSink sink(sources);
    lang::Module m = lang::load_file(std::string(CATPLAN_SOURCE_DIR) + "/" + file, sources, sink);
    CATPLAN_ASSERT(!sink.has_errors(), "an example has errors");
    return m;
}

} // namespace catplan::db::testing
