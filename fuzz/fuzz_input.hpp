#pragma once
// What every fuzz harness shares: the input as a registered buffer, the inputs of the repository it
// checks against (read once), and a drain for diagnostics so that rendering them is fuzzed too.

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/source.hpp"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

/// The entry point libFuzzer (or replay_main.cpp) calls with each input.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace catplan::fuzz {

/// One input with its own sources and diagnostics, as one run of catplan has. Its display name
/// is in a directory that does not exist, so that a relative `@import` finds nothing on disk.
struct Input {
    SourceManager sources;
    DiagnosticSink sink{sources};
    std::string name;
    std::string text;

    Input(const std::uint8_t* data, std::size_t size, const char* base)
        : name(std::string("/nonexistent-fuzz-input/") + base),
          text(reinterpret_cast<const char*>(data), size) {}

    /// Registers the text as a buffer (for the readers that take a file id).
    std::uint32_t add() { return sources.add_buffer(name, text); }

    /// Renders every diagnostic (the caret and line code is part of every reader's output).
    void drain() const { static_cast<void>(sink.render()); }
};

/// The text of a file of the repository (CATPLAN_SOURCE_DIR), "" when it cannot be read.
inline std::string repo_file(const std::string& path) {
    std::ifstream in(std::string(CATPLAN_SOURCE_DIR) + "/" + path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace catplan::fuzz
