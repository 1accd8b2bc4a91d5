#include "catplan/base/heap.hpp"
#include "catplan/base/keep.hpp"
#include "catplan/cli/commands.hpp"

#include <iostream>

int main(int argc, char** argv) {
    // Before the heap grows: a short command then takes one page fault for its heap, not hundreds.
    catplan::back_heap_with_huge_pages();
    // Then, while there is memory for the reserve that a failed allocation releases.
    catplan::cli::install_process_guards();
    // The process ends with the command: what the command is done with need not be freed.
    catplan::set_process_ends_after_command(true);
    return catplan::cli::run_protected(
        [&] { return catplan::cli::run(argc, argv, std::cout, std::cerr); }, std::cout, std::cerr);
}
