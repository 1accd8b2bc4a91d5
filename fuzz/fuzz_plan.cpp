// Fuzzes the catplan plan reader (plan::parse_plan), then the replay of what it read on the
// ColorBlocksworld case study of examples/ and the plan written back.

#include "catplan/lang/module.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/plan/validate.hpp"

#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"

namespace {

// The problem the plans are replayed on, read once.
catplan::plan::ProblemPtr case_study() {
    static const catplan::plan::ProblemPtr p = [] {
        catplan::SourceManager sources;
        catplan::DiagnosticSink sink{sources};
        auto m = catplan::lang::load_file(std::string(CATPLAN_SOURCE_DIR) +
                                              "/examples/colorblocksworld/colorblocksworld.cp",
                                          sources, sink);
        const auto* d = m.find("CaseStudy");
        if (d == nullptr || d->problem == nullptr) {
            std::fprintf(stderr, "fuzz_plan: cannot load the case study\n%s",
                         sink.render().c_str());
            std::abort();
        }
        return d->problem;
    }();
    return p;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    auto problem = case_study();
    catplan::fuzz::Input in(data, size, "input.plan");
    auto file = in.add();
    if (auto plan = catplan::plan::parse_plan(file, in.sources, in.sink)) {
        static_cast<void>(plan->to_string());
        static_cast<void>(catplan::plan::validate_plan(*problem, *plan));
    }
    in.drain();
    return 0;
}
