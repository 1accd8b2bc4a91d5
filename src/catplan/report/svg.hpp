#pragma once
// DOT to SVG for pages that inline their pictures. Graphviz's library (libgvc) lays the graph out
// in-process when catplan was built with its header (CATPLAN_HAVE_GVC); it is loaded at the first
// picture, and when it cannot be, every picture is a failure that says why. Built without the
// header, the `dot` program is run, and its absence is an error that says so.
//
//   SvgRenderer r;
//   auto svg = r.render(dot::schema_to_dot(*schema));
//   if (svg) page += inline_svg(*svg, "schema");

#include "catplan/base/result.hpp"

#include <memory>
#include <string>
#include <string_view>

namespace catplan::report {

/// Renders DOT to SVG; one renderer per thread (Graphviz's context is not thread-safe).
class SvgRenderer {
public:
    SvgRenderer();
    ~SvgRenderer();
    SvgRenderer(const SvgRenderer&) = delete;
    SvgRenderer& operator=(const SvgRenderer&) = delete;

    /// The SVG document Graphviz's dot layout makes of `dot`, or why there is none.
    Result<std::string> render(std::string_view dot);

    /// "libgvc <version>" or "dot program" (or why neither): how pictures are made, for the
    /// page's footer.
    static std::string backend();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// An SVG document made fit for inlining in HTML: the XML declaration, DOCTYPE and comments
/// removed, and every id (and reference to one) prefixed with `prefix` so that pictures on one
/// page do not share ids.
std::string inline_svg(std::string_view svg, std::string_view prefix);

} // namespace catplan::report
