// Fuzzes the PDDL problem reader (pddl::parse_problem) against each domain of tests/pddl, then the
// import of the problem into states and the export back to PDDL.

#include "catplan/pddl/export.hpp"
#include "catplan/pddl/import.hpp"
#include "catplan/pddl/pddl.hpp"

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_input.hpp"

namespace {

// The domains, read once in one SourceManager. Each input registers the same texts first, so that
// a diagnostic on the problem that points into its domain has the same file id.
struct Domains {
    std::vector<std::string> paths, texts;
    std::vector<catplan::pddl::Domain> domains;
};

const Domains& domains() {
    static const Domains all = [] {
        Domains r;
        catplan::SourceManager sources;
        catplan::DiagnosticSink sink{sources};
        for (const char* name : {"blocksworld", "gripper", "logistics"}) {
            std::string path = std::string("tests/pddl/") + name + "-domain.pddl";
            r.paths.push_back(path);
            r.texts.push_back(catplan::fuzz::repo_file(path));
            auto d = catplan::pddl::parse_domain(sources.add_buffer(path, r.texts.back()), sources,
                                                 sink);
            if (!d) {
                std::fprintf(stderr, "fuzz_pddl_problem: cannot read %s\n%s", path.c_str(),
                             sink.render().c_str());
                std::abort();
            }
            r.domains.push_back(std::move(*d));
        }
        return r;
    }();
    return all;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto& all = domains();
    catplan::fuzz::Input in(data, size, "problem.pddl");
    for (std::size_t i = 0; i < all.paths.size(); ++i) {
        in.sources.add_buffer(all.paths[i], all.texts[i]);
    }
    auto file = in.add();
    for (const auto& d : all.domains) {
        if (auto p = catplan::pddl::parse_problem(file, d, in.sources, in.sink)) {
            if (auto im = catplan::pddl::import_pddl(d, &*p, in.sink)) {
                static_cast<void>(catplan::pddl::export_problem(*im->problem));
            }
        }
    }
    in.drain();
    return 0;
}
