// Every ```catplan block of docs/language.md must load without errors and every
// ```catplan-error block must produce at least one, so the documentation cannot drift.

#include "catplan/lang/module.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace catplan::lang {
namespace {

struct Block {
    std::string text;
    int line;
    bool expect_error;
};

std::vector<Block> blocks() {
    std::ifstream in(std::string(CATPLAN_SOURCE_DIR) + "/docs/language.md");
    std::vector<Block> out;
    std::string line;
    int n = 0;
    Block* open = nullptr;
    while (std::getline(in, line)) {
        ++n;
        if (open == nullptr && (line == "```catplan" || line == "```catplan-error")) {
            out.push_back({"", n + 1, line == "```catplan-error"});
            open = &out.back();
        } else if (open != nullptr && line == "```") {
            open = nullptr;
        } else if (open != nullptr) {
            open->text += line + "\n";
        }
    }
    return out;
}

TEST(LanguageDoc, CodeBlocksBehaveAsMarked) {
    auto all = blocks();
    ASSERT_GE(all.size(), 8u) << "docs/language.md lost its examples";
    for (const auto& b : all) {
        SCOPED_TRACE("docs/language.md block at line " + std::to_string(b.line));
        SourceManager sources;
        DiagnosticSink sink(sources);
        Module m = load_source("language.md", b.text, sources, sink);
        if (b.expect_error) {
            EXPECT_TRUE(sink.has_errors()) << b.text;
        } else {
            EXPECT_FALSE(sink.has_errors()) << sink.render();
            EXPECT_FALSE(m.declarations().empty());
        }
    }
}

} // namespace
} // namespace catplan::lang
