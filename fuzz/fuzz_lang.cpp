// Fuzzes the catplan language: lexing, parsing and elaboration (lang::load_source), then the
// summaries and printers of what elaborated.

#include "catplan/lang/module.hpp"

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    catplan::fuzz::Input in(data, size, "input.cp");
    auto m = catplan::lang::load_source(in.name, in.text, in.sources, in.sink);
    in.drain();
    for (const auto& d : m.declarations()) {
        static_cast<void>(catplan::lang::summarize(d));
    }
    return 0;
}
