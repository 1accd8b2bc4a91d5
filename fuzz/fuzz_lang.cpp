// Fuzzes the catplan language: lexing, parsing and elaboration (lang::load_source), then the
// summaries and printers of what elaborated.

#include "catplan/lang/module.hpp"

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    catplan::fuzz::Input in(data, size, "input.cp");
    // Tables of millions of parts are valid and take a second to build, but many seconds under
    // the sanitizers: the fuzzer explores the language with a smaller limit, which the same check
    // enforces.
    catplan::lang::LoadOptions options;
    options.max_table_parts = 100'000;
    auto m = catplan::lang::load_source(in.name, in.text, in.sources, in.sink, options);
    in.drain();
    for (const auto& d : m.declarations()) {
        static_cast<void>(catplan::lang::summarize(d));
    }
    return 0;
}
