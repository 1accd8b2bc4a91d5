#include "catplan/base/symbol.hpp"

#include <deque>
#include <mutex>
#include <unordered_map>

namespace catplan {
namespace {

struct SymbolTable {
    std::mutex mutex;
    std::deque<std::string> texts{std::string()}; // deque: stable addresses for the views below
    std::unordered_map<std::string_view, std::uint32_t> ids{{std::string_view(), 0}};
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
    auto id = static_cast<std::uint32_t>(t.texts.size());
    t.texts.emplace_back(text);
    t.ids.emplace(t.texts.back(), id);
    return Symbol(id);
}

std::string_view Symbol::str() const {
    auto& t = table();
    std::lock_guard lock(t.mutex);
    return t.texts[id_];
}

} // namespace catplan
