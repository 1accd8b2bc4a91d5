#include "catplan/base/symbol.hpp"

#include "catplan/base/assert.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace catplan {
namespace {

// Texts live in chunks of kChunk strings that never move, so str() reads without locking: a
// Symbol's text was written, under the mutex, before the Symbol was handed out, and its chunk
// pointer is published with release and read with acquire. intern() locks.
constexpr std::uint32_t kChunkBits = 12;
constexpr std::uint32_t kChunk = 1u << kChunkBits;
constexpr std::uint32_t kMaxChunks = 1u << 20;

// The chunk pointers (8 MB) are zero-initialized static storage, so that only the pages of the
// chunks in use are ever touched: zeroing them when the table is made cost every process start.
// Plain pointers read and written through std::atomic_ref: an array of a million std::atomic is
// more than clang will evaluate as a constant initializer.
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
        std::uint32_t c = id >> kChunkBits;
        CATPLAN_ASSERT(c < kMaxChunks, "the symbol table is full");
        std::string* chunk = chunk_pointer(c).load(std::memory_order_relaxed);
        if (chunk == nullptr) {
            chunk = new std::string[kChunk]; // owned by the table for the life of the process
            chunk_pointer(c).store(chunk, std::memory_order_release);
        }
        chunk[id & (kChunk - 1)] = std::string(text);
        ids.emplace(chunk[id & (kChunk - 1)], id);
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
    const std::string* chunk = chunk_pointer(id_ >> kChunkBits).load(std::memory_order_acquire);
    return chunk[id_ & (kChunk - 1)];
}

} // namespace catplan
