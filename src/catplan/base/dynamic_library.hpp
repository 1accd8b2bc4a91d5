#pragma once
// Shared libraries loaded at their first use rather than linked. The dynamic loader maps and
// relocates every linked library before main runs, so a library that only some commands need
// (PostgreSQL's client, Graphviz, ICU) would slow every command's start; loaded here, it costs
// only the commands that use it. A library is opened by its soname (dlopen), its symbols are
// looked up by name into a struct of pointers whose types come from the library's own header,
// and it stays loaded for the rest of the process. When the library or one of its symbols is
// missing, the caller gets the reason and decides what the user is told; nothing crashes.
//
//   struct Zlib { decltype(&::zlibVersion) version = nullptr; };
//   void bind_zlib(SymbolBinder& b, Zlib& z) { b.function(z.version, "zlibVersion"); }
//   LazyLibrary<Zlib>& zlib() {
//       static LazyLibrary<Zlib> lib("libz.so.1", "zlib (Debian's zlib1g)", bind_zlib);
//       return lib;
//   }
//   std::string why;
//   if (const Zlib* z = zlib().load(why)) puts(z->version()); else report(why);

#include "catplan/base/assert.hpp"

#include <mutex>
#include <string>
#include <string_view>
#include <type_traits>

namespace catplan {

/// Looks up symbols by name in one library opened with dlopen, and keeps the first failure.
class SymbolBinder {
public:
    /// Opens the library `soname` (never closed); `name` names it in reasons, e.g. "libpq
    /// (Debian's libpq5)".
    SymbolBinder(const char* soname, std::string name);

    /// Whether the library and every symbol asked for so far were found.
    bool ok() const { return why_.empty(); }

    /// Why not ("cannot load NAME: <the loader's message>", "NAME has no symbol SYMBOL"), the
    /// first failure; empty when ok().
    const std::string& why() const { return why_; }

    /// Points `f` at the function `symbol`; it stays null when the symbol is missing.
    template <class F>
    void function(F& f, const char* symbol) {
        static_assert(std::is_pointer_v<F> && std::is_function_v<std::remove_pointer_t<F>>,
                      "a function pointer");
        f = reinterpret_cast<F>(address(symbol));
    }

    /// Points `p` at the variable `symbol` (a library's data, such as a table of callbacks); it
    /// stays null when the symbol is missing.
    template <class T>
    void data(T*& p, const char* symbol) {
        p = static_cast<T*>(address(symbol));
    }

private:
    void* address(const char* symbol);

    void* handle_ = nullptr;
    std::string name_;
    std::string why_;
};

/// A library's symbols (a struct of pointers, filled by `bind`), loaded at the first call of
/// load from any thread, once, and kept for the process's life.
template <class Symbols>
class LazyLibrary {
public:
    using Bind = void (*)(SymbolBinder&, Symbols&);

    /// The library `soname`, `name` for reasons (see SymbolBinder); nothing is loaded yet.
    LazyLibrary(const char* soname, const char* name, Bind bind)
        : soname_(soname), name_(name), bind_(bind) {}

    LazyLibrary(const LazyLibrary&) = delete;
    LazyLibrary& operator=(const LazyLibrary&) = delete;

    /// The symbols, the library loaded on the first call; nullptr, with the reason in `why`, when
    /// it or one of its symbols cannot be found (it is tried once: later calls give the same
    /// reason).
    const Symbols* load(std::string& why) {
        const std::string& reason = loaded();
        if (!reason.empty()) {
            why = reason;
            return nullptr;
        }
        return &symbols_;
    }

    /// The symbols, once load has succeeded (asserted).
    const Symbols& get() {
        CATPLAN_ASSERT(loaded().empty(), "a lazily loaded library used before it loaded");
        return symbols_;
    }

private:
    // Why the library is unusable, empty when it is usable; loads it on the first call.
    const std::string& loaded() {
        std::call_once(once_, [this] {
            SymbolBinder binder(soname_, name_);
            if (binder.ok()) {
                bind_(binder, symbols_);
            }
            why_ = binder.why();
        });
        return why_;
    }

    const char* soname_;
    const char* name_;
    Bind bind_;
    std::once_flag once_;
    Symbols symbols_{};
    std::string why_;
};

/// Whether a library whose file name contains `name` ("libicuuc") is mapped into this process
/// (read from /proc/self/maps): what tests ask to see that a library was not loaded early.
bool library_is_mapped(std::string_view name);

} // namespace catplan
