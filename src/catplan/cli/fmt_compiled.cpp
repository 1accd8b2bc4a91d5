// The catplan command carries fmt's compiled part in itself, so that it needs neither libfmt.so
// nor, through it, libstdc++.so at start-up (see the executable in CMakeLists.txt). Debian ships
// fmt as a shared library and its headers only; the functions that libfmt.so would export are
// defined here from Debian's own fmt/format-inl.h, which the header-only mode of fmt also uses.
// The libraries and the tests still link libfmt.so.
#include <fmt/format-inl.h>

namespace fmt {
inline namespace v9 {
namespace detail {
// fmt/format.h declares these two templates extern; libfmt.so instantiates them for char.
template FMT_API auto thousands_sep_impl<char>(locale_ref) -> thousands_sep_result<char>;
template FMT_API auto decimal_point_impl(locale_ref) -> char;
} // namespace detail
} // namespace v9
} // namespace fmt
