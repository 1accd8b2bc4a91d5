#include "catplan/base/heap.hpp"
#include "catplan/cli/commands.hpp"

#include <iostream>

int main(int argc, char** argv) {
    // Before the heap grows: a short command then takes one page fault for its heap, not hundreds.
    catplan::back_heap_with_huge_pages();
    // Then, while there is memory for the reserve that a failed allocation releases.
    catplan::cli::install_process_guards();
    return catplan::cli::run_protected(
        [&] { return catplan::cli::run(argc, argv, std::cout, std::cerr); }, std::cout, std::cerr);
}
