// Fuzzes plan transfer with PDDL inputs: the input is an IPC plan, read (pddl_transfer::read_plan)
// against two settings, and what is read is transferred (transfer::transfer_plan) and checked
// (pddl_transfer::check): the 3-operator blocksworld carried into the 4-operator one, every move
// repaired (examples/pddl/blocks/three_to_four.cp on p01-3), and roads carried into charters,
// every drive repaired at least cost with repairs reused by shape and values
// (tests/pddl/roads_to_transit.cp on roads-chain).

#include "catplan/pddl_transfer/pddl_transfer.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "fuzz_input.hpp"

namespace {

using catplan::pddl_transfer::Setting;

// A map's file loaded and one setting of it, kept for the whole run.
struct Loaded {
    catplan::SourceManager sources;
    catplan::DiagnosticSink sink{sources};
    catplan::lang::Module module;
    std::optional<Setting> setting;

    Loaded(const std::string& file, const std::string& map, const std::string& problem) {
        const std::string root = CATPLAN_SOURCE_DIR;
        module = catplan::lang::load_file(root + "/" + file, sources, sink);
        const auto* decl = module.find(map);
        auto pf = sources.add_file(root + "/" + problem);
        if (decl != nullptr && pf && !sink.has_errors()) {
            setting = catplan::pddl_transfer::load_setting(module, *decl, *pf, std::nullopt,
                                                           sources, sink);
        }
        if (!setting) {
            std::fprintf(stderr, "fuzz_transfer: cannot load %s\n%s", file.c_str(),
                         sink.render().c_str());
            std::abort();
        }
    }
};

const Loaded& blocks() {
    static const auto l = std::make_unique<Loaded>(
        "examples/pddl/blocks/three_to_four.cp", "ThreeToFour", "examples/pddl/blocks/p01-3.pddl");
    return *l;
}

const Loaded& roads() {
    static const auto l = std::make_unique<Loaded>("tests/pddl/roads_to_transit.cp", "ToCharters",
                                                   "tests/pddl/roads-chain.pddl");
    return *l;
}

void transfer(const Setting& s, const std::uint8_t* data, std::size_t size) {
    catplan::fuzz::Input in(data, size, "input.plan");
    auto file = in.add();
    if (auto plan = catplan::pddl_transfer::read_plan(s, file, in.sources, in.sink)) {
        auto t = catplan::transfer::transfer_plan(
            *s.map, *s.source->problem, catplan::pddl_transfer::source_plan(s, *plan),
            catplan::pddl_transfer::transfer_options(s, *plan));
        static_cast<void>(t.verdict.reason());
        static_cast<void>(catplan::pddl_transfer::check(s, *plan, t));
    }
    in.drain();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    transfer(*blocks().setting, data, size);
    transfer(*roads().setting, data, size);
    return 0;
}
