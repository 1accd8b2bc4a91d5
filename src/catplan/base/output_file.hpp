#pragma once
// Output files are written whole or not at all: the text goes to a temporary file in the same
// directory, which is then renamed over the target, so a failed run never leaves a partial file.

#include <string>
#include <string_view>

namespace catplan {

/// Writes contents to path through a temporary file and a rename; on failure returns false and
/// sets error, leaving any existing file at path untouched.
bool write_file_atomically(const std::string& path, std::string_view contents, std::string& error);

} // namespace catplan
