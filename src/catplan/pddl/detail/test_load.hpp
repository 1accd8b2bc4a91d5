#pragma once
// Loading PDDL files and texts for the pddl layer's tests (header-only).

#include "catplan/pddl/import.hpp"
#include "catplan/pddl/ipc_plan.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>

namespace catplan::pddl::testing {

/// A file of tests/pddl/.
inline std::string data(const std::string& name) {
    return std::string(CATPLAN_SOURCE_DIR) + "/tests/pddl/" + name;
}

/// Everything loaded from files, with the sources kept alive for diagnostics.
struct Loaded {
    SourceManager sources;
    DiagnosticSink sink{sources};
    std::optional<Domain> domain;
    std::optional<Problem> problem;
    std::optional<Import> import;

    std::string errors() const { return sink.render(); }
};

/// A domain and (when not empty) a problem read from texts and imported; what failed is null.
inline std::unique_ptr<Loaded> load_text(const std::string& domain_text,
                                         const std::string& problem_text) {
    auto l = std::make_unique<Loaded>();
    l->domain =
        parse_domain(l->sources.add_buffer("domain.pddl", domain_text), l->sources, l->sink);
    if (!l->domain) {
        return l;
    }
    if (!problem_text.empty()) {
        l->problem = parse_problem(l->sources.add_buffer("problem.pddl", problem_text), *l->domain,
                                   l->sources, l->sink);
        if (!l->problem) {
            return l;
        }
    }
    l->import = import_pddl(*l->domain, l->problem ? &*l->problem : nullptr, l->sink);
    return l;
}

/// The text of a file ("" after a failed expectation).
inline std::string read(const std::string& path) {
    SourceManager sm;
    auto f = sm.add_file(path);
    EXPECT_TRUE(f.has_value()) << path;
    return f ? std::string(sm.text(*f)) : "";
}

/// load_text of two files of tests/pddl/ (the problem may be "").
inline std::unique_ptr<Loaded> load(const std::string& domain, const std::string& problem) {
    return load_text(read(data(domain)), problem.empty() ? "" : read(data(problem)));
}

/// An IPC plan read from a text (empty after a failed expectation).
inline IpcPlan plan_text(const std::string& text) {
    SourceManager sm;
    DiagnosticSink sink(sm);
    auto p = parse_ipc_plan(sm.add_buffer("plan", text), sm, sink);
    EXPECT_TRUE(p.has_value()) << sink.render();
    return p.value_or(IpcPlan{});
}

} // namespace catplan::pddl::testing
