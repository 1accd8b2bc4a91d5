#include "catplan/base/source.hpp"

#include "catplan/base/assert.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace catplan {

std::size_t bom_length(std::string_view text) {
    return text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
}

namespace {

// The whole of an open stream, or the reason it cannot be read (a directory opens but fails
// here, with EISDIR).
Result<std::string> read_all(std::FILE* in) {
    std::string text;
    char chunk[1 << 16];
    while (true) {
        std::size_t n = std::fread(chunk, 1, sizeof chunk, in);
        text.append(chunk, n);
        if (n < sizeof chunk) {
            break;
        }
    }
    if (std::ferror(in) != 0) {
        return fail(std::strerror(errno));
    }
    return text;
}

} // namespace

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
    CATPLAN_ASSERT(buf->text.size() < UINT32_MAX, "source offsets are 32-bit");
    buf->line_starts.push_back(0);
    const std::string& t = buf->text;
    for (std::uint32_t i = 0; i < t.size(); ++i) {
        // LF, CRLF and a lone CR each end a line.
        if (t[i] == '\n' || (t[i] == '\r' && (i + 1 == t.size() || t[i + 1] != '\n'))) {
            buf->line_starts.push_back(i + 1);
        }
    }
    files_.push_back(std::move(buf));
    return static_cast<std::uint32_t>(files_.size() - 1);
}

Result<std::uint32_t> SourceManager::add_file(const std::string& path) {
    if (path == "-") {
        if (read_stdin_) {
            return fail("standard input can be read only once");
        }
        read_stdin_ = true;
        auto text = read_all(stdin);
        if (!text) {
            return fail(text.error());
        }
        return add_buffer("<stdin>", std::move(*text));
    }
    std::FILE* in = std::fopen(path.c_str(), "rb");
    if (in == nullptr) {
        return fail(std::strerror(errno));
    }
    auto text = read_all(in);
    std::fclose(in);
    if (!text) {
        return fail(text.error());
    }
    if (text->size() >= UINT32_MAX) {
        return fail("the file is larger than 4 GiB");
    }
    return add_buffer(path, std::move(*text));
}

LineCol SourceManager::line_col(std::uint32_t file, std::uint32_t offset) const {
    const auto& buf = *files_[file];
    auto it = std::upper_bound(buf.line_starts.begin(), buf.line_starts.end(), offset);
    auto line = static_cast<std::uint32_t>(it - buf.line_starts.begin());
    std::uint32_t start =
        line == 1 ? static_cast<std::uint32_t>(bom_length(buf.text)) : buf.line_starts[line - 1];
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
    std::uint32_t start =
        line == 1 ? static_cast<std::uint32_t>(bom_length(buf.text)) : buf.line_starts[line - 1];
    std::uint32_t end = line < buf.line_starts.size() ? buf.line_starts[line]
                                                      : static_cast<std::uint32_t>(buf.text.size());
    auto text = std::string_view(buf.text).substr(start, end - start);
    // Without its line end: LF, CRLF or CR.
    if (text.ends_with('\n')) {
        text.remove_suffix(1);
    }
    if (text.ends_with('\r')) {
        text.remove_suffix(1);
    }
    return text;
}

} // namespace catplan
