// Loads the paper's case study from an installed catplan and transfers the paper's plan along
// the ontology map ColorToKitchen; exits 0 only when the transfer is what the paper reports.
//   consumer examples/colorblocks_to_kitchen/appendix_map.cp examples/colorblocksworld/paper.plan

#include "catplan/lang/module.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/transfer/transfer.hpp"

#include <iostream>
#include <string>

namespace {

int fail(const std::string& why) {
    std::cerr << "consumer: " << why << "\n";
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        return fail("usage: consumer MAP_FILE PLAN_FILE");
    }
    catplan::SourceManager sources;
    catplan::DiagnosticSink sink(sources);
    auto module = catplan::lang::load_file(argv[1], sources, sink);
    auto plan_file = sources.add_file(argv[2]);
    if (!plan_file) {
        return fail(std::string("cannot read ") + argv[2]);
    }
    auto plan = catplan::plan::parse_plan(*plan_file, sources, sink);
    if (sink.has_errors() || !plan) {
        std::cerr << sink.render();
        return fail("the inputs have errors");
    }
    const auto* map = module.find("ColorToKitchen");
    const auto* problem = module.find("CaseStudy");
    if (map == nullptr || map->map == nullptr || problem == nullptr || !problem->problem) {
        return fail("ColorToKitchen or CaseStudy is missing");
    }
    auto t = catplan::transfer::transfer_plan(*map->map, *problem->problem, *plan);
    const auto& v = t.verdict;
    std::cout << "transferred " << t.steps.size() << " steps; goal " << v.goal.satisfied << "/"
              << v.goal.total << "; " << (v.valid() ? "valid" : "invalid: " + v.reason()) << "\n";
    for (const auto& step : t.steps) {
        std::cout << "  " << step.target.to_string() << "\n";
    }
    if (!v.valid() || t.steps.size() != 8 || t.steps[0].target.to_string() != "unstack(E, D)" ||
        v.goal.satisfied != v.goal.total || v.goal.total == 0) {
        return fail("the transfer is not the paper's");
    }
    return 0;
}
