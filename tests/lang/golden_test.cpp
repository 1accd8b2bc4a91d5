// Runs one golden case per tests/lang/<case>.cp: the expected output is <case>.out (for each
// declaration its summary and its describe / to_tables form) or <case>.err (the rendered
// diagnostics). File names are relative to the repository root so the goldens hold no absolute
// paths. CATPLAN_UPDATE_GOLDEN=1 rewrites the expectation instead of comparing.

#include "catplan/acset/printer.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/schema/printer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> cases() {
    std::vector<std::string> out;
    std::stringstream ss(CATPLAN_LANG_CASES);
    std::string item;
    while (std::getline(ss, item, ',')) {
        out.push_back(item);
    }
    return out;
}

std::string read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

class LangGolden : public testing::TestWithParam<std::string> {};

TEST_P(LangGolden, MatchesExpectation) {
    std::filesystem::current_path(CATPLAN_SOURCE_DIR);
    const std::string stem = "tests/lang/" + GetParam();
    catplan::SourceManager sources;
    catplan::DiagnosticSink sink(sources);
    auto module = catplan::lang::load_file(stem + ".cp", sources, sink);
    std::string actual;
    std::string expected_path;
    if (sink.has_errors()) {
        actual = sink.render();
        expected_path = stem + ".err";
    } else {
        for (const auto& d : module.declarations()) {
            actual += catplan::lang::summarize(d) + "\n";
            actual += d.kind == catplan::lang::DeclKind::Schema
                          ? catplan::schema::describe(*d.schema)
                          : catplan::acset::to_tables(*d.instance);
            actual += "\n";
        }
        expected_path = stem + ".out";
    }
    const char* update = std::getenv("CATPLAN_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        std::filesystem::remove(stem + ".out");
        std::filesystem::remove(stem + ".err");
        std::ofstream(expected_path, std::ios::binary) << actual;
        return;
    }
    ASSERT_TRUE(std::filesystem::exists(expected_path))
        << "missing " << expected_path << "; the output was:\n"
        << actual;
    EXPECT_EQ(read(expected_path), actual);
}

INSTANTIATE_TEST_SUITE_P(Cases, LangGolden, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<std::string>& param) {
                             return param.param;
                         });

} // namespace
