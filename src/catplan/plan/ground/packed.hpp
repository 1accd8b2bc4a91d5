#pragma once
// Packed states of a ground task and the registry that stores each once (as Fast Downward's
// IntPacker and StateRegistry do): a variable of n values takes ceil(log2 n) bits, a mutex group
// of n atoms (mutexes.hpp) one field of ceil(log2(n + 1)) bits holding which atom is present (0:
// none), fields are packed into 64-bit words without crossing a word boundary, and states are
// compared exactly.
//
// The registry keeps states in segments of fixed size and an open-addressing table of ids; before
// the table grows it asks the budget whether the new table fits in the memory limit (limits.hpp),
// and throws LimitReached when it does not, so a search never passes the limit by a doubling.

#include "catplan/plan/ground/task.hpp"
#include "catplan/plan/limits.hpp"

#include <memory>
#include <vector>

namespace catplan::plan::ground {

using StateId = std::uint32_t;
using Word = std::uint64_t;

class StatePacker {
public:
    explicit StatePacker(const Task& task);

    std::uint32_t words() const { return words_; }

    std::uint32_t get(const Word* s, VarId v) const {
        const Slot& sl = slots_[v];
        std::uint32_t raw = field(s, sl);
        return sl.member == 0 ? raw : static_cast<std::uint32_t>(raw == sl.member);
    }

    /// Sets v's value; for an atom of a mutex group, absent leaves another atom present.
    void set(Word* s, VarId v, std::uint32_t value) const {
        const Slot& sl = slots_[v];
        std::uint32_t raw = value;
        if (sl.member != 0) {
            if (value == 0 && field(s, sl) != sl.member) {
                return;
            }
            raw = value == 0 ? 0 : sl.member;
        }
        s[sl.word] = (s[sl.word] & ~(sl.mask << sl.shift)) | (Word{raw} << sl.shift);
    }

    /// Packs a value per variable (at most one atom of a mutex group present).
    void pack(const std::vector<std::uint32_t>& values, Word* s) const;
    /// Unpacks into a value per variable.
    void unpack(const Word* s, std::vector<std::uint32_t>& values) const;

    /// Bytes per packed state.
    std::size_t bytes() const { return words_ * sizeof(Word); }

private:
    struct Slot {
        std::uint32_t word = 0, shift = 0;
        Word mask = 0;
        std::uint32_t member = 0; // an atom of a mutex group: its index in the group + 1
    };

    static std::uint32_t field(const Word* s, const Slot& sl) {
        return static_cast<std::uint32_t>((s[sl.word] >> sl.shift) & sl.mask);
    }

    std::vector<Slot> slots_;
    std::uint32_t words_ = 0;
};

class StateRegistry {
public:
    StateRegistry(const StatePacker& packer, Budget& budget);

    struct Insertion {
        StateId id;
        bool is_new;
    };

    /// The id of the stored state equal to s, storing a copy of s when there is none.
    Insertion insert(const Word* s);

    const Word* state(StateId id) const {
        return segments_[id / per_segment_].get() + std::size_t(id % per_segment_) * words_;
    }

    std::size_t size() const { return size_; }

    /// Bytes held (segments and table).
    std::size_t bytes() const;

private:
    std::uint64_t hash(const Word* s) const;
    bool equal(const Word* a, const Word* b) const;
    void grow();
    Word* slot_for(StateId id);

    Budget& budget_;
    std::uint32_t words_;
    std::uint32_t per_segment_;
    std::vector<std::unique_ptr<Word[]>> segments_;
    std::vector<StateId> table_; // kNone: empty
    std::size_t size_ = 0;
};

} // namespace catplan::plan::ground
