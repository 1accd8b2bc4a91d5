#include "catplan/base/diagnostic.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan {

Diagnostic& DiagnosticSink::error(SourceRange range, std::string message) {
    ++num_errors_;
    diagnostics_.push_back({Severity::Error, range, std::move(message), {}, false});
    return diagnostics_.back();
}

Diagnostic& DiagnosticSink::unsupported(SourceRange range, std::string message) {
    Diagnostic& d = error(range, std::move(message));
    d.unsupported = true;
    return d;
}

bool DiagnosticSink::only_unsupported() const {
    return num_errors_ > 0 &&
           std::all_of(diagnostics_.begin(), diagnostics_.end(), [](const Diagnostic& d) {
               return d.severity != Severity::Error || d.unsupported;
           });
}

Diagnostic& DiagnosticSink::warning(SourceRange range, std::string message) {
    diagnostics_.push_back({Severity::Warning, range, std::move(message), {}, false});
    return diagnostics_.back();
}

Diagnostic& DiagnosticSink::note(SourceRange range, std::string message) {
    diagnostics_.push_back({Severity::Note, range, std::move(message), {}, false});
    return diagnostics_.back();
}

Diagnostic& DiagnosticSink::add(Diagnostic d) {
    if (d.severity == Severity::Error) {
        ++num_errors_;
    }
    diagnostics_.push_back(std::move(d));
    return diagnostics_.back();
}

namespace {

const char* severity_name(Severity s) {
    switch (s) {
    case Severity::Error:
        return "error";
    case Severity::Warning:
        return "warning";
    case Severity::Note:
        return "note";
    }
    return "error";
}

// Columns are counted in code points; tabs are kept so the caret lines up in a terminal.
std::string caret_line(std::string_view line, std::uint32_t col, std::uint32_t width) {
    std::string out;
    std::uint32_t c = 1;
    for (std::size_t i = 0; i < line.size() && c < col; ++i) {
        auto ch = static_cast<unsigned char>(line[i]);
        if ((ch & 0xC0) == 0x80) {
            continue;
        }
        out += line[i] == '\t' ? '\t' : ' ';
        ++c;
    }
    out += '^';
    for (std::uint32_t i = 1; i < width; ++i) {
        out += '~';
    }
    return out;
}

// A line longer than this many code points is shown as a window around the column, so that a
// one-line JSON file of a megabyte gives a readable message instead of the whole file.
constexpr std::uint32_t kMaxShownColumns = 160;
constexpr std::uint32_t kColumnsBefore = 60;
constexpr std::string_view kEllipsis = "...";

bool is_continuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// The byte offset of code point `n` (0-based) of `line`, or line.size() past its end.
std::size_t code_point_offset(std::string_view line, std::uint32_t n) {
    std::size_t i = 0;
    for (std::uint32_t c = 0; i < line.size(); ++i) {
        if (!is_continuation(line[i]) && c++ == n) {
            return i;
        }
    }
    return line.size();
}

// The part of `line` shown for a caret at code point column `col` (1-based), with `col` moved
// to where it falls in what is shown; short lines are shown whole.
std::string window(std::string_view line, std::uint32_t& col, std::uint32_t& width) {
    std::size_t length = static_cast<std::size_t>(
        std::count_if(line.begin(), line.end(), [](char c) { return !is_continuation(c); }));
    if (length <= kMaxShownColumns) {
        return std::string(line);
    }
    std::uint32_t first = col > kColumnsBefore ? col - 1 - kColumnsBefore : 0;
    std::uint32_t last =
        std::min<std::uint32_t>(static_cast<std::uint32_t>(length), first + kMaxShownColumns);
    std::size_t b = code_point_offset(line, first), e = code_point_offset(line, last);
    std::string out;
    if (first > 0) {
        out += kEllipsis;
    }
    out += line.substr(b, e - b);
    if (last < length) {
        out += kEllipsis;
    }
    std::uint32_t shift = first > 0 ? static_cast<std::uint32_t>(kEllipsis.size()) : 0;
    col = col - first + shift;
    width = std::max<std::uint32_t>(1, std::min(width, shift + (last - first) + 1 - col));
    return out;
}

} // namespace

std::string DiagnosticSink::render_one(Severity severity, SourceRange range,
                                       const std::string& message) const {
    if (!range.valid()) {
        return fmt::format("catplan: {}: {}\n", severity_name(severity), message);
    }
    auto start = sources_->line_col(range.file, range.begin);
    auto stop = sources_->line_col(range.file, std::max(range.begin, range.end));
    std::uint32_t width = 1;
    if (stop.line == start.line && stop.col > start.col) {
        width = stop.col - start.col;
    }
    std::uint32_t col = start.col;
    auto text = window(sources_->line_text(range.file, start.line), col, width);
    auto gutter = fmt::format("{:>5}", start.line);
    return fmt::format("{}:{}:{}: {}: {}\n{} | {}\n{} | {}\n", sources_->name(range.file),
                       start.line, start.col, severity_name(severity), message, gutter, text,
                       std::string(gutter.size(), ' '), caret_line(text, col, width));
}

std::string DiagnosticSink::render(const Diagnostic& d) const {
    std::string out = render_one(d.severity, d.range, d.message);
    for (const auto& [range, note] : d.notes) {
        out += render_one(Severity::Note, range, note);
    }
    return out;
}

std::string DiagnosticSink::render_from(std::size_t first) const {
    std::vector<const Diagnostic*> sorted;
    for (std::size_t i = first; i < diagnostics_.size(); ++i) {
        sorted.push_back(&diagnostics_[i]);
    }
    std::stable_sort(sorted.begin(), sorted.end(), [](const Diagnostic* a, const Diagnostic* b) {
        if (a->range.file != b->range.file) {
            return a->range.file < b->range.file;
        }
        return a->range.begin < b->range.begin;
    });
    std::string out;
    for (const auto* d : sorted) {
        out += render(*d);
    }
    return out;
}

} // namespace catplan
