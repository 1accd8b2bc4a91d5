#include "catplan/base/symbol.hpp"

#include "catplan/base/assert.hpp"

#include <atomic>
#include <bit>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace catplan {
namespace {

// Texts live in chunks that never move, so str() reads without locking: a Symbol's text was
// written, under the mutex, before the Symbol was handed out, and its chunk pointer is published
// with release and read with acquire. intern() locks. Chunk k holds kFirst << k texts, so that a
// short command touches only the few pages its symbols need (a first chunk of 4,096 strings,
// 128 KB constructed at the first intern, was a tenth of the page faults of a small transfer)
// and 32 chunks hold every 32-bit id.
constexpr std::uint32_t kFirstBits = 6;
constexpr std::uint64_t kFirst = std::uint64_t{1} << kFirstBits;
constexpr std::uint32_t kMaxChunks = 32;

struct Slot {
    std::uint32_t chunk;
    std::uint64_t offset;
};

// Chunk k starts at id kFirst * (2^k - 1).
Slot slot_of(std::uint32_t id) {
    std::uint64_t q = (std::uint64_t{id} >> kFirstBits) + 1;
    auto k = static_cast<std::uint32_t>(std::bit_width(q) - 1);
    return {k, id - kFirst * ((std::uint64_t{1} << k) - 1)};
}

// Plain pointers, zero-initialized static storage, read and written through std::atomic_ref.
std::string* chunk_table[kMaxChunks];

std::atomic_ref<std::string*> chunk_pointer(std::uint32_t c) {
    return std::atomic_ref<std::string*>(chunk_table[c]);
}

struct SymbolTable {
    std::mutex mutex;
    std::uint32_t size = 0;
    std::unordered_map<std::string_view, std::uint32_t> ids;

    SymbolTable() { add(std::string_view()); } // id 0 is the empty string

    std::uint32_t add(std::string_view text) {
        std::uint32_t id = size;
        CATPLAN_ASSERT(id != UINT32_MAX, "the symbol table is full");
        Slot at = slot_of(id);
        std::string* chunk = chunk_pointer(at.chunk).load(std::memory_order_relaxed);
        if (chunk == nullptr) {
            // Owned by the table for the life of the process.
            chunk = new std::string[kFirst << at.chunk];
            chunk_pointer(at.chunk).store(chunk, std::memory_order_release);
        }
        chunk[at.offset] = std::string(text);
        ids.emplace(chunk[at.offset], id);
        ++size;
        return id;
    }
};

SymbolTable& table() {
    static SymbolTable t;
    return t;
}

} // namespace

Symbol Symbol::intern(std::string_view text) {
    auto& t = table();
    std::lock_guard lock(t.mutex);
    if (auto it = t.ids.find(text); it != t.ids.end()) {
        return Symbol(it->second);
    }
    return Symbol(t.add(text));
}

std::string_view Symbol::str() const {
    if (id_ == 0) {
        return {};
    }
    Slot at = slot_of(id_);
    const std::string* chunk = chunk_pointer(at.chunk).load(std::memory_order_acquire);
    return chunk[at.offset];
}

} // namespace catplan
