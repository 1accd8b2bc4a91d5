#pragma once

#include <cstddef>
#include <cstdint>

namespace catplan {

/// Mixes v into the running hash h (64-bit variant of boost::hash_combine with a murmur finaliser).
constexpr std::uint64_t hash_combine(std::uint64_t h, std::uint64_t v) {
    v *= 0xff51afd7ed558ccdULL;
    v ^= v >> 33;
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h;
}

/// A strong 64-bit mix of one value (splitmix64 finaliser).
constexpr std::uint64_t hash_mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

} // namespace catplan
