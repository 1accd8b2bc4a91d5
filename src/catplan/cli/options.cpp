#include "catplan/cli/options.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

namespace catplan::cli {
namespace {

// The text quoted in a message: short, so that a 300-digit argument does not fill the screen.
std::string quoted(const std::string& text) {
    return text.size() <= 40 ? "'" + text + "'" : "'" + text.substr(0, 37) + "...'";
}

// The subcommands `app` was given, in the order they were added.
std::vector<const CLI::App*> subcommands_of(const CLI::App& app) {
    return app.get_subcommands([](const CLI::App*) { return true; });
}

// The path of an app from the top: "catplan json export".
std::string command_path(const CLI::App& app) {
    std::string path = app.get_name();
    for (const auto* p = app.get_parent(); p != nullptr; p = p->get_parent()) {
        path = p->get_name() + " " + path;
    }
    return path;
}

} // namespace

std::string check_positive_number(const std::string& text, std::string_view unit) {
    std::string expected = fmt::format("expected a positive number of {}", unit);
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size() || std::isnan(v)) {
        return fmt::format("{}, not {}", expected, quoted(text));
    }
    if (!std::isfinite(v) || errno == ERANGE) {
        return fmt::format("{}, not {} (too large; leave the option out for no limit)", expected,
                           quoted(text));
    }
    if (v <= 0) {
        return fmt::format("{}, not {} (leave the option out for no limit)", expected,
                           quoted(text));
    }
    return "";
}

std::string check_positive_count(const std::string& text) {
    std::uint64_t v = 0;
    const char* begin = text.data() + (text.rfind('+', 0) == 0 ? 1 : 0);
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(begin, end, v);
    if (begin == end || ec == std::errc::invalid_argument || ptr != end) {
        return fmt::format("expected a whole number of at least 1, not {}", quoted(text));
    }
    if (ec == std::errc::result_out_of_range) {
        return fmt::format("expected a whole number of at least 1, not {} (too large; leave the "
                           "option out for no limit)",
                           quoted(text));
    }
    if (v == 0) {
        return "expected a whole number of at least 1, not '0' (leave the option out for no "
               "limit)";
    }
    return "";
}

CLI::Validator positive_number(std::string unit) {
    return CLI::Validator([unit](std::string& text) { return check_positive_number(text, unit); },
                          "POSITIVE", "positive number");
}

CLI::Validator positive_count() {
    return CLI::Validator([](std::string& text) { return check_positive_count(text); }, "POSITIVE",
                          "positive count");
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::optional<std::string> closest_name(std::string_view word,
                                        const std::vector<std::string>& names) {
    std::optional<std::string> best;
    std::size_t best_distance = 0;
    for (const auto& n : names) {
        std::size_t d = edit_distance(word, n);
        std::size_t longer = std::max(word.size(), n.size());
        if (d < longer && 3 * d <= longer + 2 && (!best || d < best_distance)) {
            best = n;
            best_distance = d;
        }
    }
    return best;
}

const CLI::App& command_for(const CLI::App& app, const std::vector<std::string>& args) {
    const CLI::App* current = &app;
    for (const auto& word : args) {
        auto subs = subcommands_of(*current);
        if (subs.empty()) {
            break; // a leaf: its words are its own arguments
        }
        auto it = std::find_if(subs.begin(), subs.end(),
                               [&](const CLI::App* s) { return s->check_name(word); });
        if (it != subs.end()) {
            current = *it;
        } else if (word.empty() || word[0] != '-') {
            break; // not an option of this level (--help, --version): not a subcommand
        }
    }
    return *current;
}

std::optional<std::string> subcommand_error(const CLI::App& app,
                                            const std::vector<std::string>& args) {
    const CLI::App& command = command_for(app, args);
    auto subs = subcommands_of(command);
    if (subs.empty()) {
        return std::nullopt;
    }
    std::vector<std::string> names;
    for (const auto* s : subs) {
        names.push_back(s->get_name());
    }
    // The word after the command's own, if any, is the one that named no subcommand.
    std::size_t depth = 0;
    for (const auto* p = &command; p != &app; p = p->get_parent()) {
        ++depth;
    }
    std::size_t seen = 0;
    for (const auto& word : args) {
        if (!word.empty() && word[0] == '-') {
            continue;
        }
        if (seen++ < depth) {
            continue;
        }
        auto guess = closest_name(word, names);
        return fmt::format("unknown subcommand {} of '{}'{}", quoted(word), command_path(command),
                           guess ? fmt::format("; did you mean '{}'?", *guess)
                                 : fmt::format(" (one of: {})", fmt::join(names, ", ")));
    }
    return fmt::format("'{}' needs a subcommand: one of {}", command_path(command),
                       fmt::join(names, ", "));
}

void usage_error(std::ostream& err, const CLI::App& app, const std::string& message) {
    err << "catplan: error: " << message << "\n"
        << fmt::format("catplan: run '{} --help' for the usage\n", command_path(app));
}

} // namespace catplan::cli
