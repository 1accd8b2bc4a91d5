#include "catplan/cli/common.hpp"

#include <CLI/CLI.hpp>

namespace catplan::cli {

void add_report_commands(CLI::App& app, CommandTable& table) {
    (void)app;
    (void)table;
}

} // namespace catplan::cli
