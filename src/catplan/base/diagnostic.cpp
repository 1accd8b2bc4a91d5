#include "catplan/base/diagnostic.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan {

Diagnostic& DiagnosticSink::error(SourceRange range, std::string message) {
    ++num_errors_;
    diagnostics_.push_back({Severity::Error, range, std::move(message), {}});
    return diagnostics_.back();
}

Diagnostic& DiagnosticSink::warning(SourceRange range, std::string message) {
    diagnostics_.push_back({Severity::Warning, range, std::move(message), {}});
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
    auto text = sources_->line_text(range.file, start.line);
    auto gutter = fmt::format("{:>5}", start.line);
    return fmt::format("{}:{}:{}: {}: {}\n{} | {}\n{} | {}\n", sources_->name(range.file),
                       start.line, start.col, severity_name(severity), message, gutter, text,
                       std::string(gutter.size(), ' '), caret_line(text, start.col, width));
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
