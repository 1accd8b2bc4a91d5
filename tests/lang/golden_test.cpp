// Runs one golden case per tests/lang/<case>.cp: the expected output is <case>.out (for each
// declaration its summary and its describe / to_tables form; for a rule its L, K, R and the maps
// l and r; for a domain the summary of each rule; for a map each generator's image) or <case>.err
// (the rendered diagnostics). File names are relative to the repository root so the goldens hold no
// absolute paths. CATPLAN_UPDATE_GOLDEN=1 rewrites the expectation instead of comparing.

#include "catplan/acset/printer.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/migrate/describe.hpp"
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

// "  Block: block -> block, #3 -> #4" per object with parts, by labels.
std::string print_map(const catplan::hom::ACSetMorphism& f, const catplan::acset::ACSet& from,
                      const catplan::acset::ACSet& to) {
    std::string out;
    const auto& s = from.schema();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        catplan::ObId ob(o);
        if (from.num_parts(ob) == 0) {
            continue;
        }
        out += "  " + s.ob(ob).name + ":";
        for (catplan::Part p = 0; p < from.num_parts(ob); ++p) {
            out += (p == 0 ? " " : ", ") + from.part_label(ob, p) + " -> " +
                   to.part_label(ob, f(ob, p));
        }
        out += "\n";
    }
    return out;
}

std::string print_declaration(const catplan::lang::Declaration& d) {
    using catplan::lang::DeclKind;
    std::string out = catplan::lang::summarize(d) + "\n";
    switch (d.kind) {
    case DeclKind::Schema:
        return out + catplan::schema::describe(*d.schema) + "\n";
    case DeclKind::Instance:
        return out + catplan::acset::to_tables(*d.instance) + "\n";
    case DeclKind::Rule: {
        const auto& r = *d.rule;
        out += "L:\n" + catplan::acset::to_tables(r.L) + "K:\n" + catplan::acset::to_tables(r.K) +
               "R:\n" + catplan::acset::to_tables(r.R);
        out += "l:\n" + print_map(r.l, r.K, r.L) + "r:\n" + print_map(r.r, r.K, r.R);
        for (const auto& c : r.conditions) {
            out += c.name + ":\n" + catplan::acset::to_tables(c.n_state);
        }
        return out + "\n";
    }
    case DeclKind::Domain:
        for (const auto& r : d.domain->rules) {
            out += "  " + catplan::lang::summarize_rule(*r) + "\n";
        }
        return out + "\n";
    case DeclKind::Problem:
        return out + "\n";
    case DeclKind::Map:
        return out + catplan::migrate::map_text(catplan::migrate::describe_map(*d.map)) + "\n";
    }
    return out;
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
            actual += print_declaration(d);
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
