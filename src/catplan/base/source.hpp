#pragma once
// Source text kept in memory, so a diagnostic can quote its line long after parsing. Locations are
// byte offsets into a buffer; line and column (1-based, the column counted in UTF-8 code points so
// that `→` counts once) are computed on demand. A line ends at LF, CRLF or a lone CR; a UTF-8
// byte-order mark at the start of a buffer takes no column.
//
// The name "-" reads standard input (once per SourceManager, shown as `<stdin>`), as Unix tools do.

#include "catplan/base/result.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace catplan {

/// How deeply any reader lets its input nest (brackets, calls, blocks, operators, JSON arrays and
/// objects): deeper input is a located error, so that neither parsing nor the recursive walks of
/// the trees read can exhaust the stack.
inline constexpr std::uint32_t kMaxNesting = 256;

/// The number of bytes (3 or 0) of a UTF-8 byte-order mark at the start of text.
std::size_t bom_length(std::string_view text);

/// A byte range [begin, end) in one buffer of a SourceManager; file == kNoFile means "nowhere".
struct SourceRange {
    static constexpr std::uint32_t kNoFile = UINT32_MAX;
    std::uint32_t file = kNoFile;
    std::uint32_t begin = 0;
    std::uint32_t end = 0;

    bool valid() const { return file != kNoFile; }

    /// The smallest range covering both (which must be in the same file, or one invalid).
    SourceRange merge(SourceRange other) const;
};

struct LineCol {
    std::uint32_t line = 0;
    std::uint32_t col = 0;
};

class SourceManager {
public:
    /// Registers a buffer under a display name and returns its file id.
    std::uint32_t add_buffer(std::string name, std::string text);
    /// Reads a file ("-": standard input, named `<stdin>`); fails with the reason ("Is a
    /// directory", "No such file or directory", ...) when it cannot be read.
    Result<std::uint32_t> add_file(const std::string& path);

    std::string_view name(std::uint32_t file) const { return files_[file]->name; }

    std::string_view text(std::uint32_t file) const { return files_[file]->text; }

    std::size_t num_files() const { return files_.size(); }

    /// Line and column of a byte offset.
    LineCol line_col(std::uint32_t file, std::uint32_t offset) const;
    /// The text of a 1-based line, without its newline.
    std::string_view line_text(std::uint32_t file, std::uint32_t line) const;

private:
    struct Buffer {
        std::string name;
        std::string text;
        std::vector<std::uint32_t> line_starts;
    };

    std::vector<std::unique_ptr<Buffer>> files_;
    bool read_stdin_ = false;
};

} // namespace catplan
