#include "catplan/plan/ground/packed.hpp"

#include "catplan/base/hash.hpp"
#include "catplan/plan/ground/mutexes.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace catplan::plan::ground {

StatePacker::StatePacker(const Task& task) {
    // Fields: one per mutex group, one per other variable, each with its variables.
    std::vector<std::vector<VarId>> fields = disjoint_groups(task.mutex_groups);
    std::vector<char> grouped(task.vars.size(), 0);
    for (const auto& g : fields) {
        for (VarId v : g) {
            CATPLAN_ASSERT(grouped[v] == 0, "mutex groups are disjoint");
            grouped[v] = 1;
        }
    }
    for (VarId v = 0; v < task.vars.size(); ++v) {
        if (grouped[v] == 0) {
            fields.push_back({v});
        }
    }
    // Widest fields first, each into the first word with room (first fit decreasing).
    std::vector<std::pair<std::uint32_t, std::size_t>> by_width;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const auto& f = fields[i];
        auto n = f.size() > 1 ? static_cast<std::uint32_t>(f.size()) + 1 : task.vars[f[0]].size();
        by_width.emplace_back(std::bit_width(std::max<std::uint32_t>(n, 2) - 1), i);
    }
    std::stable_sort(by_width.begin(), by_width.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    slots_.resize(task.vars.size());
    std::vector<std::uint32_t> used; // bits used per word
    for (auto [bits, i] : by_width) {
        CATPLAN_ASSERT(bits <= 32, "a variable with more than 2^32 values");
        std::uint32_t w = 0;
        while (w < used.size() && used[w] + bits > 64) {
            ++w;
        }
        if (w == used.size()) {
            used.push_back(0);
        }
        const auto& f = fields[i];
        for (std::uint32_t k = 0; k < f.size(); ++k) {
            slots_[f[k]] = {w, used[w], (Word{1} << bits) - 1, f.size() > 1 ? k + 1 : 0};
        }
        used[w] += bits;
    }
    words_ = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(used.size()));
}

void StatePacker::pack(const std::vector<std::uint32_t>& values, Word* s) const {
    std::fill(s, s + words_, Word{0});
    for (VarId v = 0; v < values.size(); ++v) {
        if (values[v] != 0 && slots_[v].member != 0) {
            CATPLAN_ASSERT(field(s, slots_[v]) == 0, "two atoms of a mutex group present");
        }
        set(s, v, values[v]);
    }
}

void StatePacker::unpack(const Word* s, std::vector<std::uint32_t>& values) const {
    values.resize(slots_.size());
    for (VarId v = 0; v < slots_.size(); ++v) {
        values[v] = get(s, v);
    }
}

namespace {

constexpr std::size_t kSegmentBytes = std::size_t{1} << 20;

} // namespace

StateRegistry::StateRegistry(const StatePacker& packer, Budget& budget)
    : budget_(budget),
      words_(packer.words()),
      per_segment_(static_cast<std::uint32_t>(
          std::max<std::size_t>(1, kSegmentBytes / (packer.words() * sizeof(Word))))),
      table_(1024, kNone) {}

std::uint64_t StateRegistry::hash(const Word* s) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (std::uint32_t i = 0; i < words_; ++i) {
        h = hash_combine(h, s[i]);
    }
    return hash_mix(h);
}

bool StateRegistry::equal(const Word* a, const Word* b) const {
    return std::memcmp(a, b, words_ * sizeof(Word)) == 0;
}

Word* StateRegistry::slot_for(StateId id) {
    std::size_t seg = id / per_segment_;
    if (seg == segments_.size()) {
        std::size_t bytes = std::size_t(per_segment_) * words_ * sizeof(Word);
        if (budget_.would_exceed(bytes)) {
            throw LimitReached{SearchStatus::MemoryLimit};
        }
        segments_.push_back(
            std::make_unique_for_overwrite<Word[]>(std::size_t(per_segment_) * words_));
    }
    return segments_[seg].get() + std::size_t(id % per_segment_) * words_;
}

void StateRegistry::grow() {
    std::size_t n = table_.size() * 2;
    if (budget_.would_exceed(n * sizeof(StateId))) {
        throw LimitReached{SearchStatus::MemoryLimit};
    }
    std::vector<StateId> bigger(n, kNone);
    for (StateId id : table_) {
        if (id == kNone) {
            continue;
        }
        std::size_t i = hash(state(id)) & (n - 1);
        while (bigger[i] != kNone) {
            i = (i + 1) & (n - 1);
        }
        bigger[i] = id;
    }
    table_.swap(bigger);
}

StateRegistry::Insertion StateRegistry::insert(const Word* s) {
    if ((size_ + 1) * 2 > table_.size()) {
        grow();
    }
    std::size_t mask = table_.size() - 1;
    std::size_t i = hash(s) & mask;
    while (table_[i] != kNone) {
        if (equal(state(table_[i]), s)) {
            return {table_[i], false};
        }
        i = (i + 1) & mask;
    }
    CATPLAN_ASSERT(size_ < kNone, "more than 2^32 states");
    auto id = static_cast<StateId>(size_);
    Word* dst = slot_for(id);
    std::memcpy(dst, s, words_ * sizeof(Word));
    table_[i] = id;
    ++size_;
    return {id, true};
}

std::size_t StateRegistry::bytes() const {
    return segments_.size() * std::size_t(per_segment_) * words_ * sizeof(Word) +
           table_.size() * sizeof(StateId);
}

} // namespace catplan::plan::ground
