#include "catplan/base/source.hpp"

#include "catplan/base/assert.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace catplan {

SourceRange SourceRange::merge(SourceRange other) const {
    if (!valid()) {
        return other;
    }
    if (!other.valid()) {
        return *this;
    }
    CATPLAN_ASSERT(file == other.file, "merging ranges of different files");
    return {file, std::min(begin, other.begin), std::max(end, other.end)};
}

std::uint32_t SourceManager::add_buffer(std::string name, std::string text) {
    auto buf = std::make_unique<Buffer>();
    buf->name = std::move(name);
    buf->text = std::move(text);
    buf->line_starts.push_back(0);
    for (std::uint32_t i = 0; i < buf->text.size(); ++i) {
        if (buf->text[i] == '\n') {
            buf->line_starts.push_back(i + 1);
        }
    }
    files_.push_back(std::move(buf));
    return static_cast<std::uint32_t>(files_.size() - 1);
}

std::optional<std::uint32_t> SourceManager::add_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return std::nullopt;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) {
        return std::nullopt;
    }
    return add_buffer(path, ss.str());
}

LineCol SourceManager::line_col(std::uint32_t file, std::uint32_t offset) const {
    const auto& buf = *files_[file];
    auto it = std::upper_bound(buf.line_starts.begin(), buf.line_starts.end(), offset);
    auto line = static_cast<std::uint32_t>(it - buf.line_starts.begin());
    std::uint32_t start = buf.line_starts[line - 1];
    std::uint32_t col = 1;
    for (std::uint32_t i = start; i < offset && i < buf.text.size(); ++i) {
        // Count code points: skip UTF-8 continuation bytes.
        if ((static_cast<unsigned char>(buf.text[i]) & 0xC0) != 0x80) {
            ++col;
        }
    }
    return {line, col};
}

std::string_view SourceManager::line_text(std::uint32_t file, std::uint32_t line) const {
    const auto& buf = *files_[file];
    CATPLAN_ASSERT(line >= 1 && line <= buf.line_starts.size(), "line out of range");
    std::uint32_t start = buf.line_starts[line - 1];
    std::uint32_t end = line < buf.line_starts.size() ? buf.line_starts[line] - 1
                                                      : static_cast<std::uint32_t>(buf.text.size());
    std::string_view view(buf.text);
    auto text = view.substr(start, end - start);
    if (!text.empty() && text.back() == '\r') {
        text.remove_suffix(1);
    }
    return text;
}

} // namespace catplan
