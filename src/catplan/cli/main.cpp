#include "catplan/cli/commands.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return catplan::cli::run(argc, argv, std::cout, std::cerr);
}
