// Fuzzes the IPC plan reader (pddl::parse_ipc_plan), then the validation of what it read on the
// blocksworld problem of tests/pddl and the plan written back.

#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"
#include "catplan/pddl/pddl.hpp"

#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"

namespace {

// The domain and problem the plans are replayed on, read once.
const catplan::pddl::Import& blocksworld() {
    static const catplan::pddl::Import im = [] {
        catplan::SourceManager sources;
        catplan::DiagnosticSink sink{sources};
        auto df = sources.add_buffer(
            "domain.pddl", catplan::fuzz::repo_file("tests/pddl/blocksworld-domain.pddl"));
        auto pf = sources.add_buffer("problem.pddl",
                                     catplan::fuzz::repo_file("tests/pddl/blocksworld-p01.pddl"));
        auto d = catplan::pddl::parse_domain(df, sources, sink);
        auto p = d ? catplan::pddl::parse_problem(pf, *d, sources, sink) : std::nullopt;
        auto r = p ? catplan::pddl::import_pddl(*d, &*p, sink) : std::nullopt;
        if (!r) {
            std::fprintf(stderr, "fuzz_ipc_plan: cannot import blocksworld\n%s",
                         sink.render().c_str());
            std::abort();
        }
        return std::move(*r);
    }();
    return im;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto& im = blocksworld();
    catplan::fuzz::Input in(data, size, "input.plan");
    auto file = in.add();
    if (auto plan = catplan::pddl::parse_ipc_plan(file, in.sources, in.sink)) {
        static_cast<void>(catplan::pddl::write_ipc_plan(*plan));
        static_cast<void>(catplan::pddl::validate_ipc_plan(im, *plan));
    }
    in.drain();
    return 0;
}
