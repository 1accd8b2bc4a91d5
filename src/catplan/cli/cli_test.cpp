// The command line's own checks and its last line of defence.

#include "catplan/base/assert.hpp"
#include "catplan/base/out_of_memory.hpp"
#include "catplan/cli/commands.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/cli/options.hpp"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace catplan::cli {
namespace {

TEST(NumericOptions, PositiveNumberAcceptsOnlyFinitePositiveNumbers) {
    for (const char* ok : {"1", "0.5", "60", "1e3", "+2"}) {
        EXPECT_EQ(check_positive_number(ok, "seconds"), "") << ok;
    }
    EXPECT_EQ(check_positive_number("-1", "seconds"),
              "expected a positive number of seconds, not '-1' (leave the option out for no "
              "limit)");
    EXPECT_EQ(check_positive_number("0", "seconds"),
              "expected a positive number of seconds, not '0' (leave the option out for no "
              "limit)");
    EXPECT_EQ(check_positive_number("nan", "seconds"),
              "expected a positive number of seconds, not 'nan'");
    EXPECT_EQ(check_positive_number("1e999", "megabytes"),
              "expected a positive number of megabytes, not '1e999' (too large; leave the option "
              "out for no limit)");
    EXPECT_NE(check_positive_number("inf", "seconds"), "");
    EXPECT_NE(check_positive_number("", "seconds"), "");
    EXPECT_NE(check_positive_number("5s", "seconds"), "");
    // A long argument is cut in the message, never printed in full.
    EXPECT_LT(check_positive_number(std::string(300, '9') + "x", "seconds").size(), 100u);
}

TEST(NumericOptions, PositiveCountAcceptsWholeNumbersFromOne) {
    for (const char* ok : {"1", "5", "+7", "18446744073709551615"}) {
        EXPECT_EQ(check_positive_count(ok), "") << ok;
    }
    EXPECT_EQ(check_positive_count("0"),
              "expected a whole number of at least 1, not '0' (leave the option out for no limit)");
    EXPECT_EQ(check_positive_count("-1"), "expected a whole number of at least 1, not '-1'");
    EXPECT_EQ(check_positive_count("2.5"), "expected a whole number of at least 1, not '2.5'");
    EXPECT_NE(check_positive_count("18446744073709551616").find("too large"), std::string::npos);
    EXPECT_NE(check_positive_count(""), "");
}

TEST(Subcommands, EditDistanceAndClosestName) {
    EXPECT_EQ(edit_distance("chek", "check"), 1u);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
    EXPECT_EQ(edit_distance("same", "same"), 0u);
    std::vector<std::string> names{"check", "show", "homs", "migrate", "migrate-domain"};
    EXPECT_EQ(closest_name("chek", names), "check");
    EXPECT_EQ(closest_name("migrat", names), "migrate");
    EXPECT_EQ(closest_name("migrate-domian", names), "migrate-domain");
    EXPECT_EQ(closest_name("hom", names), "homs");
    EXPECT_EQ(closest_name("xyzzy", names), std::nullopt);
}

// run() on a command line, with what it printed.
struct Ran {
    int code;
    std::string out, err;
};

Ran run_args(std::vector<std::string> args) {
    args.insert(args.begin(), "catplan");
    std::vector<char*> argv;
    for (auto& a : args) {
        argv.push_back(a.data());
    }
    std::ostringstream out, err;
    int code = run(static_cast<int>(argv.size()), argv.data(), out, err);
    return {code, out.str(), err.str()};
}

TEST(Subcommands, UnknownOrMissingSubcommandIsAUsageErrorWithASuggestion) {
    auto r = run_args({"chek", "x.cp"});
    EXPECT_EQ(r.code, kBadInput);
    EXPECT_EQ(r.err, "catplan: error: unknown subcommand 'chek' of 'catplan'; did you mean "
                     "'check'?\ncatplan: run 'catplan --help' for the usage\n");
    r = run_args({"json", "exprot"});
    EXPECT_EQ(r.code, kBadInput);
    EXPECT_EQ(r.err, "catplan: error: unknown subcommand 'exprot' of 'catplan json'; did you mean "
                     "'export'?\ncatplan: run 'catplan json --help' for the usage\n");
    r = run_args({"pddl"});
    EXPECT_EQ(r.err, "catplan: error: 'catplan pddl' needs a subcommand: one of import, export\n"
                     "catplan: run 'catplan pddl --help' for the usage\n");
    r = run_args({"show", "--frobnicate", "a.cp", "X"});
    EXPECT_EQ(r.code, kBadInput);
    EXPECT_EQ(r.err.rfind("catplan: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("catplan: run 'catplan show --help' for the usage"), std::string::npos);
}

// run() builds only the group of the command named, so each group must add exactly the
// commands it is listed with, and no command may be in two groups.
TEST(Subcommands, EachGroupAddsExactlyTheCommandsItNames) {
    std::vector<std::string> all;
    for (const auto& g : command_groups()) {
        CLI::App app;
        CommandTable table;
        g.add(app, table);
        std::vector<std::string> added, named(g.names.begin(), g.names.end());
        for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
            added.push_back(sub->get_name());
        }
        EXPECT_EQ(added, named);
        all.insert(all.end(), named.begin(), named.end());
    }
    std::sort(all.begin(), all.end());
    EXPECT_EQ(std::adjacent_find(all.begin(), all.end()), all.end());
    EXPECT_EQ(all.size(), 14u);
    // A command runs with only its group built, and help still lists every command.
    auto r = run_args({"--help"});
    EXPECT_EQ(r.code, kOk);
    for (const auto& name : all) {
        EXPECT_NE(r.out.find("  " + name + " "), std::string::npos) << name;
    }
}

TEST(PddlImport, WritesAFileThatLoadsWithPddlNamesQuoted) {
    // blocks4's on-table and hand-empty are no identifiers: the file writes them var"on-table".
    std::string dir = std::string(CATPLAN_SOURCE_DIR) + "/examples/pddl/blocks/";
    std::string file = ::testing::TempDir() + "catplan_import_blocks4.cp";
    auto r = run_args({"pddl", "import", dir + "blocks4.pddl", dir + "p01-4.pddl", "-o", file});
    ASSERT_EQ(r.code, kOk) << r.err;
    r = run_args({"check", file});
    EXPECT_EQ(r.code, kOk) << r.err;
    EXPECT_NE(r.out.find("instance Initial (blocks4): 11 parts (object 3, block 3, on 2, on-table "
                         "1, clear 1, hand-empty 1)"),
              std::string::npos)
        << r.out;
    std::remove(file.c_str());
}

TEST(PddlImport, CostsReadFromFunctionsLoadBackAndPlanToTheSameCost) {
    // lift's actions cost (travel-slow ?f1 ?f2), a value each problem gives: the written file
    // keeps the cost terms and the values, and A* finds a plan of the same least cost on it.
    std::string dir = std::string(CATPLAN_SOURCE_DIR) + "/tests/pddl/";
    std::string file = ::testing::TempDir() + "catplan_import_lift.cp";
    auto r =
        run_args({"pddl", "import", dir + "lift-domain.pddl", dir + "lift-p01.pddl", "-o", file});
    ASSERT_EQ(r.code, kOk) << r.err;
    auto pddl = run_args({"plan", dir + "lift-domain.pddl", dir + "lift-p01.pddl", "--search",
                          "astar", "--no-timing"});
    ASSERT_EQ(pddl.code, kOk) << pddl.err;
    EXPECT_NE(pddl.out.find("; cost = 19 (general cost)"), std::string::npos) << pddl.out;
    auto cp = run_args({"plan", file, "--problem", "lift-p01", "--search", "astar", "--no-timing"});
    ASSERT_EQ(cp.code, kOk) << cp.err;
    EXPECT_NE(cp.out.find("# cost = 19\n"), std::string::npos) << cp.out;
    EXPECT_NE(cp.out.find("summing action costs; optimal"), std::string::npos) << cp.out;
    std::remove(file.c_str());
}

TEST(NumericOptions, EveryLimitOptionIsChecked) {
    auto r = run_args({"plan", "a.cp", "--problem", "P", "--max-time", "-1"});
    EXPECT_EQ(r.code, kBadInput);
    EXPECT_EQ(r.err, "catplan: error: --max-time: expected a positive number of seconds, not '-1' "
                     "(leave the option out for no limit)\ncatplan: run 'catplan plan --help' for "
                     "the usage\n");
    for (auto args : std::vector<std::vector<std::string>>{
             {"plan", "a.cp", "--problem", "P", "--max-time", "nan"},
             {"plan", "a.cp", "--problem", "P", "--max-memory", "0"},
             {"plan", "a.cp", "--problem", "P", "--max-nodes", "0"},
             {"homs", "a.cp", "A", "B", "--all", "--max", "0"},
             {"transfer", "a.cp", "--map", "F", "--problem", "P", "--plan", "p", "--max-time",
              "inf"},
             {"report", "a.cp", "--map", "F", "--problem", "P", "--plan", "p", "--max-time",
              "0"}}) {
        r = run_args(args);
        EXPECT_EQ(r.code, kBadInput) << args.back();
        EXPECT_NE(r.err.find("catplan: error: --max"), std::string::npos) << r.err;
    }
}

TEST(Protected, EscapedExceptionsBecomeDocumentedCodes) {
    std::ostringstream out, err;
    EXPECT_EQ(run_protected(
                  [&] {
                      out << "partial\n";
                      return kOk;
                  },
                  out, err),
              kOk);
    EXPECT_EQ(run_protected([]() -> int { throw std::runtime_error("type_error.316"); }, out, err),
              kInternal);
    EXPECT_EQ(err.str(), "catplan: internal error: type_error.316 (please report it with the "
                         "input)\n");
    err.str("");
    EXPECT_EQ(run_protected([]() -> int { throw 42; }, out, err), kInternal);
    EXPECT_EQ(err.str(), "catplan: internal error: an exception that is not a std::exception "
                         "(please report it with the input)\n");
}

TEST(Protected, OutputThatCannotBeWrittenIsAnError) {
    std::ostringstream out, err;
    out.setstate(std::ios::badbit); // as std::cout on a full disk or a closed stdout
    EXPECT_EQ(run_protected([] { return kOk; }, out, err), kBadInput);
    EXPECT_EQ(err.str(), "catplan: error: cannot write the output to stdout\n");
    EXPECT_EQ(run_protected([] { return kNo; }, out, err), kNo); // the answer stays the answer
}

TEST(Protected, OutOfMemoryIsALimitWithTheNoteOfTheWork) {
    install_out_of_memory_handler(1 << 20);
    std::ostringstream out, err;
    int code = run_protected(
        []() -> int {
            OutOfMemoryNote note([] { return std::string("expanded 12, generated 40"); });
            handle_out_of_memory(); // what operator new calls when an allocation fails
        },
        out, err);
    EXPECT_EQ(code, kLimit);
    EXPECT_EQ(err.str(), "catplan: error: out of memory: the work was stopped (exit 4, a limit)\n"
                         "catplan: when memory ran out: expanded 12, generated 40\n");
    err.str("");
    EXPECT_EQ(run_protected([]() -> int { throw std::bad_alloc(); }, out, err), kLimit);
}

TEST(Protected, AssertionInACommandExitsWithTheInternalErrorCode) {
    EXPECT_EXIT(run_protected([]() -> int { CATPLAN_UNREACHABLE("broken invariant"); }, std::cout,
                              std::cerr),
                ::testing::ExitedWithCode(kInternal), "internal error: .*broken invariant");
}

} // namespace
} // namespace catplan::cli
