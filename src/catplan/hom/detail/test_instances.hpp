#pragma once
// Small schemas and instances shared by the hom layer's tests and benchmarks (header-only).

#include "catplan/acset/acset.hpp"
#include "catplan/schema/schema.hpp"

#include <cstdint>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace catplan::hom::testing {

using acset::ACSet;
using acset::Value;
using schema::Schema;
using schema::SchemaPtr;

/// The schema of directed multigraphs: V, E, src, tgt : E -> V.
inline SchemaPtr graph_schema() {
    static SchemaPtr s = [] {
        auto g = std::make_shared<Schema>("Graph");
        ObId v = g->add_ob("V"), e = g->add_ob("E");
        g->add_hom("src", e, v);
        g->add_hom("tgt", e, v);
        return SchemaPtr(g);
    }();
    return s;
}

inline constexpr ObId kV{0};
inline constexpr ObId kE{1};
inline constexpr HomId kSrc{0};
inline constexpr HomId kTgt{1};

/// A graph on the same schema with nv vertices and the given (0-based) edges, in order.
inline ACSet make_graph(SchemaPtr s, std::size_t nv,
                        const std::vector<std::pair<Part, Part>>& edges) {
    ACSet g(std::move(s));
    g.add_parts(kV, nv);
    for (auto [a, b] : edges) {
        Part e = g.add_part(kE);
        g.set_subpart(kSrc, e, a);
        g.set_subpart(kTgt, e, b);
    }
    return g;
}

inline ACSet make_graph(std::size_t nv, const std::vector<std::pair<Part, Part>>& edges) {
    return make_graph(graph_schema(), nv, edges);
}

/// 1 -> 2 -> ... -> n.
inline ACSet path_graph(std::size_t n) {
    std::vector<std::pair<Part, Part>> edges;
    for (Part i = 0; i + 1 < n; ++i) {
        edges.emplace_back(i, i + 1);
    }
    return make_graph(n, edges);
}

/// 1 -> 2 -> ... -> n -> 1.
inline ACSet cycle_graph(std::size_t n) {
    std::vector<std::pair<Part, Part>> edges;
    for (Part i = 0; i < n; ++i) {
        edges.emplace_back(i, static_cast<Part>((i + 1) % n));
    }
    return make_graph(n, edges);
}

/// Every ordered pair of distinct vertices is an edge (Catlab's complete_graph).
inline ACSet complete_graph(std::size_t n) {
    std::vector<std::pair<Part, Part>> edges;
    for (Part i = 0; i < n; ++i) {
        for (Part j = 0; j < n; ++j) {
            if (i != j) {
                edges.emplace_back(i, j);
            }
        }
    }
    return make_graph(n, edges);
}

/// Each ordered pair (u, v), u != v, is an edge with probability p (seeded, deterministic).
inline ACSet random_graph(std::size_t n, double p, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coin(0.0, 1.0);
    std::vector<std::pair<Part, Part>> edges;
    for (Part i = 0; i < n; ++i) {
        for (Part j = 0; j < n; ++j) {
            if (i != j && coin(rng) < p) {
                edges.emplace_back(i, j);
            }
        }
    }
    return make_graph(n, edges);
}

/// Discrete dynamical systems: one object X with one hom Φ : X -> X.
inline SchemaPtr dds_schema() {
    static SchemaPtr s = [] {
        auto d = std::make_shared<Schema>("DDS");
        ObId x = d->add_ob("X");
        d->add_hom("Φ", x, x);
        return SchemaPtr(d);
    }();
    return s;
}

/// A DDS with n states and a seeded random Φ.
inline ACSet random_dds(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    ACSet d(dds_schema());
    d.add_parts(ObId(0), n);
    for (Part i = 0; i < n; ++i) {
        d.set_subpart(HomId(0), i, static_cast<Part>(rng() % n));
    }
    return d;
}

} // namespace catplan::hom::testing
