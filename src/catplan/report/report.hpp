#pragma once
// An HTML report of a plan transfer, for a person: one self-contained page (inline CSS, SVG
// pictures inlined, no scripts, nothing fetched from the network) with
//   - "In brief": what the map sends each target object to and what it loses (explain.hpp);
//   - the transfer's verdict (valid or not, and why), goal satisfaction with the unsatisfied
//     statements (for the intended goal when the transfer was given one), and the kind of
//     migration;
//   - the two ontologies, the map's picture and its images in a table;
//   - the source and target plans side by side, one row per step, with the bindings of each
//     match (the target match is the source match carried through part names: that is why the
//     target step is the analogue of the source step), each target part bound with the reason
//     it is the image of the source part (explain.hpp), and, folded in <details>, the states
//     before and after the step on both sides;
//   - efficiency figures when replanning was done.
//
//   ReportInput in{.map = map.get(), .map_name = "ColorToKitchen", .problem = problem.get(),
//                  .plan = &plan, .transfer = &t};
//   auto html = html_report(in);

#include "catplan/dot/dot.hpp"
#include "catplan/migrate/schema_map.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/transfer/transfer.hpp"

#include <string>

namespace catplan::report {

/// What a report shows; the pointers must be non-null and outlive the call.
struct ReportInput {
    const migrate::SchemaMap* map = nullptr;
    std::string map_name;
    const plan::Problem* problem = nullptr;
    /// The source plan as written.
    const plan::Plan* plan = nullptr;
    /// The transfer, made with TransferOptions::keep_states for the state pictures (without it
    /// the steps are listed with no pictures).
    const transfer::TransferResult* transfer = nullptr;
    /// Replanning in the target domain, when it was done.
    const transfer::Replan* replan = nullptr;
    /// The process's peak memory right after the transfer, in KiB (0 when unknown).
    long transfer_peak_kib = 0;
    /// Leave out times and memory (for reproducible pages).
    bool no_timing = false;
    /// How states and schemas are drawn.
    dot::DotOptions dot;
};

/// The whole report as one HTML document; a picture that Graphviz cannot make is replaced by a
/// note saying why (the page is still written).
std::string html_report(const ReportInput& in);

} // namespace catplan::report
