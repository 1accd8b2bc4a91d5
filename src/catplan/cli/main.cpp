#include "catplan/cli/commands.hpp"

#include <iostream>

int main(int argc, char** argv) {
    // First of all, while there is memory for the reserve that a failed allocation releases.
    catplan::cli::install_process_guards();
    return catplan::cli::run_protected(
        [&] { return catplan::cli::run(argc, argv, std::cout, std::cerr); }, std::cout, std::cerr);
}
