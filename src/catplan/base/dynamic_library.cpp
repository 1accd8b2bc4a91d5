#include "catplan/base/dynamic_library.hpp"

#include <dlfcn.h>
#include <fstream>
#include <utility>

namespace catplan {

SymbolBinder::SymbolBinder(const char* soname, std::string name) : name_(std::move(name)) {
    // RTLD_NOW: a library that cannot resolve its own symbols fails here, with a reason, rather
    // than at some later call. RTLD_LOCAL: its symbols do not interpose on anyone else's.
    handle_ = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (handle_ == nullptr) {
        const char* e = dlerror();
        why_ = "cannot load " + name_ + ": " + (e != nullptr ? e : soname);
    }
}

void* SymbolBinder::address(const char* symbol) {
    if (handle_ == nullptr) {
        return nullptr;
    }
    void* a = dlsym(handle_, symbol);
    if (a == nullptr && why_.empty()) {
        why_ = name_ + " has no symbol " + symbol;
    }
    return a;
}

bool library_is_mapped(std::string_view name) {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) {
        if (line.find(name) != std::string::npos) {
            return true;
        }
    }
    return false;
}

} // namespace catplan
