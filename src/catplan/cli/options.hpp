#pragma once
// The command line's own checks, one mechanism each: every numeric option is validated by one of
// the two checks below (so `--max-time -1`, `0`, `nan` and `inf` all get the same clear message),
// an unknown subcommand is named with the closest known one, and every usage error is printed as
// `catplan: error: ...` with the way to the usage.
//
//   cmd->add_option("--max-time", seconds, "...")->check(positive_number("seconds"));
//   cmd->add_option("--max", n, "...")->check(positive_count());

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
class Validator;
class ParseError;
} // namespace CLI

namespace catplan::cli {

/// A check for an option holding an amount: a finite decimal number greater than 0 (not 0, a
/// negative number, nan or inf), described in messages as "a positive number of <unit>".
CLI::Validator positive_number(std::string unit);

/// A check for an option holding a count: a whole number from 1 to 2^64 - 1.
CLI::Validator positive_count();

/// The error of a number given to positive_number, "" when it is one (exposed for tests).
std::string check_positive_number(const std::string& text, std::string_view unit);
/// The error of a count given to positive_count, "" when it is one (exposed for tests).
std::string check_positive_count(const std::string& text);

/// Levenshtein distance between two names (insertions, deletions and substitutions of bytes).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name among `names` closest to `word`, when it is close enough to be a likely misspelling
/// (at most a third of the longer name changed, and at least one letter kept).
std::optional<std::string> closest_name(std::string_view word,
                                        const std::vector<std::string>& names);

/// For arguments `args` (argv without the program name) that did not parse: the message when a
/// word stands where `app` (or one of its subcommands) expects a subcommand and names none of
/// them (with the closest name), or when the subcommand is missing; nullopt otherwise.
std::optional<std::string> subcommand_error(const CLI::App& app,
                                            const std::vector<std::string>& args);

/// The deepest subcommand of `app` that `args` name (app itself when they name none).
const CLI::App& command_for(const CLI::App& app, const std::vector<std::string>& args);

/// Prints a usage error as `catplan: error: ...` and where to find the usage.
void usage_error(std::ostream& err, const CLI::App& app, const std::string& message);

} // namespace catplan::cli
