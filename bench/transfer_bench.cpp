// Plan transfer (transfer::transfer_plan, the paper's Algorithm 1) against replanning in the target
// domain (transfer::replan, the paper's Metric 5), and how transfer scales with plan length and
// state size. Figures: RESULTS.md, "Plan transfer".
//
// Everything is loaded through the language layer from the examples, as `catplan transfer` does:
//   catplan transfer examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen
//       --problem CaseStudy --plan examples/colorblocksworld/paper.plan [--replan]
// plus, declared here on top of it, a delta map BlocksToKitchenette : Kitchenette ->
// ColorBlocksworld (a renaming of ColorBlocksworld: every object to an object, every hom and
// attribute to one of the source's).
//
//   BM_CaseStudyTransfer/{conjunctive,delta}  the paper's 8-step plan along either map
//   BM_CaseStudyReplan/<config>               replanning from Δ_F(I) to Δ_F(G) with the migrated
//                                             actions, one run per configuration, each bounded by
//                                             kReplanSeconds; counters: solved, expanded,
//                                             plan_len, transfer_ms (the median of transfers timed
//                                             in the same run) and speedup = replanning time /
//                                             transfer time (a lower bound when the search hit
//                                             its limit: `solved` is 0 then), validated
//                                             (validate_plan accepts the plan found; it may call
//                                             a step ambiguous), edit_dist (to the transferred
//                                             plan); the label has the status and the plan
//   BM_TransferPlanLength/<map>/<steps>       generated plans of 10..10^4 steps on 100 blocks
//   BM_TransferStateSize/<map>/<blocks>/<steps>  a 100-step and a 10^4-step plan on 10..10^5
//                                             blocks
// The generated problems are ColorBlocksworld states built on the loaded schema: blocks b1..bn
// in towers of two (b1 under b2, b3 under b4, ...), coloured in turn purple, red, green, yellow,
// blue (the five colours the map knows), the hand empty. A plan cycles unstack(t, u), putdown(t),
// pickup(t), stack(t, u) over the towers 2, 3, ... in turn (so that consecutive cycles touch
// different blocks), cut at the wanted length; the goal is tower 1 (red on purple), which the
// plan never touches. Counters: us_per_step (the whole transfer_plan call per source step),
// apply_us_per_step (the replay-and-apply phase alone per step), migrate_ms and validate_ms (the
// once-per-transfer phases: Δ_F of the initial state, the goal check), parts (of Y_0).
//
// Every transfer is checked: it must be valid and have as many target steps as source steps;
// the program aborts otherwise. Every plan replanning finds is checked with validate_plan on the
// target problem: a step it calls ambiguous is reported (validated = 0), any other failure
// aborts. Replanning takes up to 5 x kReplanSeconds: filter it out for quick runs
// (--benchmark_filter=-Replan). Not run by ctest (no test is registered for bench programs).

#include "catplan/lang/module.hpp"
#include "catplan/plan/domain.hpp"
#include "catplan/plan/search.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/transfer/transfer.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#ifndef CATPLAN_SOURCE_DIR
#error "CATPLAN_SOURCE_DIR must name the source directory (bench/CMakeLists.txt sets it)"
#endif

namespace catplan {
namespace {

using acset::ACSet;
using acset::Value;
using migrate::SchemaMap;

constexpr double kReplanSeconds = 30.0;
constexpr std::size_t kReplanMaxBytes = std::size_t{4} << 30; // 4 GiB of stored states

[[noreturn]] void fail(const std::string& why) {
    std::fprintf(stderr, "transfer_bench: %s\n", why.c_str());
    std::abort();
}

// The delta map, declared on top of the case study's file.
constexpr const char* kDeltaText = R"(
@import "../examples/colorblocks_to_kitchen/appendix_map.cp"

@present Kitchenette(FreeSchema) begin
  (Object, Gripper, Empty, InReceptacle)::Ob
  inReceptacle_l::Hom(InReceptacle, Object)
  inReceptacle_r::Hom(InReceptacle, Object)
  isEmpty::Hom(Empty, Object)
  isHolding::Hom(Gripper, Object)
  (Label, Free, Floor)::AttrType
  hasLabel::Attr(Object, Label)
  isFree::Attr(Object, Free)
  isOnFloor::Attr(Object, Floor)
end

@migration BlocksToKitchenette(Kitchenette, ColorBlocksworld) begin
  Object => Block
  Gripper => Gripper
  Empty => Empty
  InReceptacle => On
  inReceptacle_l => on_l
  inReceptacle_r => on_r
  isEmpty => isEmpty
  isHolding => isHolding
  Label => Color
  Free => Clear
  Floor => OnTable
  hasLabel => hasColor
  isFree => isClear
  isOnFloor => isOnTable
end
)";

// What the benchmarks read from the examples, loaded once.
struct Inputs {
    SourceManager sources;
    DiagnosticSink sink{sources};
    lang::Module module;
    std::shared_ptr<const SchemaMap> conjunctive, delta;
    plan::ProblemPtr case_study;
    plan::Plan paper_plan;

    Inputs() {
        const std::string dir = CATPLAN_SOURCE_DIR;
        // The text is in memory; its name anchors the relative @import.
        module = lang::load_source(dir + "/bench/transfer_bench.cp", kDeltaText, sources, sink);
        if (sink.has_errors()) {
            fail("cannot load the examples:\n" + sink.render());
        }
        conjunctive = map("ColorToKitchen");
        delta = map("BlocksToKitchenette");
        if (conjunctive->is_delta() || !delta->is_delta()) {
            fail("ColorToKitchen must be conjunctive and BlocksToKitchenette delta");
        }
        const auto* p = module.find("CaseStudy");
        if (p == nullptr || p->kind != lang::DeclKind::Problem) {
            fail("no problem CaseStudy");
        }
        case_study = p->problem;
        auto file = sources.add_file(dir + "/examples/colorblocksworld/paper.plan");
        if (!file) {
            fail("cannot read examples/colorblocksworld/paper.plan");
        }
        auto parsed = plan::parse_plan(*file, sources, sink);
        if (!parsed || sink.has_errors()) {
            fail("cannot parse the paper's plan:\n" + sink.render());
        }
        paper_plan = std::move(*parsed);
    }

    std::shared_ptr<const SchemaMap> map(const char* name) const {
        const auto* d = module.find(name);
        if (d == nullptr || d->kind != lang::DeclKind::Map || !d->map) {
            fail(std::string("no map ") + name);
        }
        return d->map;
    }

    const SchemaMap& along(bool use_delta) const { return use_delta ? *delta : *conjunctive; }
};

const Inputs& inputs() {
    static const Inputs in;
    return in;
}

// Aborts unless t is a valid transfer of a plan of `steps` steps.
void check(const transfer::TransferResult& t, std::size_t steps) {
    if (!t.verdict.valid() || t.steps.size() != steps) {
        fail("invalid transfer (" + std::to_string(t.steps.size()) + " of " +
             std::to_string(steps) + " steps): " + t.verdict.reason());
    }
}

// ---- The case study ----------------------------------------------------------------------------

void BM_CaseStudyTransfer(benchmark::State& state, bool use_delta) {
    const auto& in = inputs();
    const auto& f = in.along(use_delta);
    for (auto _ : state) {
        auto t = transfer::transfer_plan(f, *in.case_study, in.paper_plan);
        check(t, in.paper_plan.steps.size());
        benchmark::DoNotOptimize(t);
    }
    auto t = transfer::transfer_plan(f, *in.case_study, in.paper_plan);
    state.counters["steps"] = static_cast<double>(t.steps.size());
    state.counters["parts"] = static_cast<double>(t.target_initial->total_parts());
}

BENCHMARK_CAPTURE(BM_CaseStudyTransfer, conjunctive, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_CaseStudyTransfer, delta, true)->Unit(benchmark::kMillisecond);

// The median wall time of n transfers of the case study along ColorToKitchen, in ms.
double median_transfer_ms(int n) {
    const auto& in = inputs();
    std::vector<double> ms;
    for (int i = 0; i < n; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        auto t = transfer::transfer_plan(*in.conjunctive, *in.case_study, in.paper_plan);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
        check(t, in.paper_plan.steps.size());
    }
    std::nth_element(ms.begin(), ms.begin() + n / 2, ms.end());
    return ms[n / 2];
}

// One bounded replanning run (Iterations(1)); the case study's transfer is timed in the same run.
void BM_CaseStudyReplan(benchmark::State& state, plan::SearchKind search,
                        plan::HeuristicKind heuristic) {
    const auto& in = inputs();
    auto t = transfer::transfer_plan(*in.conjunctive, *in.case_study, in.paper_plan);
    check(t, in.paper_plan.steps.size());
    plan::SearchOptions so;
    so.search = search;
    so.heuristic = heuristic;
    so.max_seconds = kReplanSeconds;
    so.max_bytes = kReplanMaxBytes;
    transfer::Replan r;
    for (auto _ : state) {
        r = transfer::replan(t, so);
        benchmark::DoNotOptimize(r);
    }
    const bool solved = r.search.status == plan::SearchStatus::Solved;
    bool validated = false;
    if (solved) {
        // The plan found must be valid on the target problem (Y_0, Δ_F(G), migrated actions).
        plan::Problem target;
        target.name = "replan";
        target.domain = t.target_domain.domain;
        target.initial = t.target_initial;
        target.goal = t.target_goal;
        if (!r.search.plan || r.steps.size() != r.search.plan->steps.size()) {
            fail("replanning says solved but returned no plan");
        }
        // The search replays its own matches; validate_plan resolves each step from its
        // arguments and may find them ambiguous (the migrated actions' parameters do not cover
        // the hand-empty marker's Object and Receptacle), which is reported, not an error.
        auto v = plan::validate_plan(target, *r.search.plan);
        validated = v.valid;
        if (!v.valid && v.reason.find("ambiguous") == std::string::npos) {
            fail("replanning found an invalid plan: " + v.reason + "\n" +
                 r.search.plan->to_string());
        }
    }
    const double transfer_ms = median_transfer_ms(101);
    state.counters["solved"] = solved ? 1 : 0;
    state.counters["expanded"] = static_cast<double>(r.search.stats.expanded);
    state.counters["generated"] = static_cast<double>(r.search.stats.generated);
    state.counters["plan_len"] = solved ? static_cast<double>(r.steps.size()) : 0;
    state.counters["validated"] = validated ? 1 : 0;
    state.counters["edit_dist"] = solved ? static_cast<double>(r.edit_distance) : 0;
    state.counters["replan_ms"] = r.ms;
    state.counters["transfer_ms"] = transfer_ms;
    state.counters["speedup"] = r.ms / transfer_ms;
    state.counters["peak_MiB"] = static_cast<double>(r.peak_rss_kib) / 1024.0;
    std::string label(plan::to_string(r.search.status));
    if (solved) {
        label += ": " + r.search.plan->to_string();
        std::replace(label.begin(), label.end(), '\n', ';');
    }
    state.SetLabel(label);
}

using plan::HeuristicKind;
using plan::SearchKind;
// The configurations that run into the time limit are run once whatever --benchmark_repetitions
// says: a repetition would measure the limit again.
BENCHMARK_CAPTURE(BM_CaseStudyReplan, astar_hadd, SearchKind::AStar, HeuristicKind::HAdd)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(1);
BENCHMARK_CAPTURE(BM_CaseStudyReplan, astar_hff, SearchKind::AStar, HeuristicKind::HFF)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_CaseStudyReplan, astar_goalcount, SearchKind::AStar, HeuristicKind::GoalCount)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(1);
BENCHMARK_CAPTURE(BM_CaseStudyReplan, gbfs_hff, SearchKind::GreedyBestFirst, HeuristicKind::HFF)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_CaseStudyReplan, bfs, SearchKind::BreadthFirst, HeuristicKind::Blind)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(1);

// ---- Generated blocksworld plans ---------------------------------------------------------------

// The ColorBlocksworld ids, looked up by name in the loaded schema.
struct Ids {
    ObId block, empty, gripper, on;
    HomId on_l, on_r, is_empty, is_holding;
    AttrId color, clear, table;
    AttrTypeId color_t, clear_t, table_t;

    explicit Ids(const schema::Schema& s)
        : block(ob(s, "Block")),
          empty(ob(s, "Empty")),
          gripper(ob(s, "Gripper")),
          on(ob(s, "On")),
          on_l(hom(s, "on_l")),
          on_r(hom(s, "on_r")),
          is_empty(hom(s, "isEmpty")),
          is_holding(hom(s, "isHolding")),
          color(attr(s, "hasColor")),
          clear(attr(s, "isClear")),
          table(attr(s, "isOnTable")),
          color_t(type(s, "Color")),
          clear_t(type(s, "Clear")),
          table_t(type(s, "OnTable")) {}

    template <class T>
    static T need(std::optional<T> id, const char* name) {
        if (!id) {
            fail(std::string("ColorBlocksworld has no ") + name);
        }
        return *id;
    }

    static ObId ob(const schema::Schema& s, const char* n) { return need(s.find_ob(n), n); }

    static HomId hom(const schema::Schema& s, const char* n) { return need(s.find_hom(n), n); }

    static AttrId attr(const schema::Schema& s, const char* n) { return need(s.find_attr(n), n); }

    static AttrTypeId type(const schema::Schema& s, const char* n) {
        return need(s.find_attr_type(n), n);
    }
};

constexpr const char* kColors[] = {"purple", "red", "green", "yellow", "blue"};

std::string block_name(std::size_t i) {
    return "b" + std::to_string(i + 1);
}

// n blocks (n even, at least 4) in towers of two, the hand empty; the goal tower 1 (b2 on b1).
plan::ProblemPtr generated_problem(std::size_t n) {
    const auto& in = inputs();
    const auto& domain = in.case_study->domain;
    auto s = domain->schema;
    Ids id(*s);
    ACSet x(s);
    x.reserve(id.block, n + 1);
    x.reserve(id.on, n / 2);
    for (std::size_t i = 0; i < n; ++i) {
        Part b = x.add_part(id.block, block_name(i));
        bool top = i % 2 == 1;
        x.set_subpart(id.color, b, Value::string(kColors[i % 5]));
        x.set_subpart(id.clear, b, Value::boolean(top));
        x.set_subpart(id.table, b, Value::boolean(!top));
        if (top) {
            Part o = x.add_part(id.on, "x" + std::to_string(i / 2 + 1));
            x.set_subpart(id.on_l, o, b);
            x.set_subpart(id.on_r, o, b - 1);
        }
    }
    // The hand-empty marker, as in the case study: unnamed, its attributes unknown.
    Part marker = x.add_part(id.block);
    x.set_subpart(id.color, marker, x.add_var(id.color_t));
    x.set_subpart(id.clear, marker, x.add_var(id.clear_t));
    x.set_subpart(id.table, marker, x.add_var(id.table_t));
    x.set_subpart(id.is_holding, x.add_part(id.gripper, "gripper"), marker);
    x.set_subpart(id.is_empty, x.add_part(id.empty, "empty"), marker);

    ACSet g(s);
    Part gt = g.add_part(id.block, "top"), gb = g.add_part(id.block, "bottom");
    g.set_subpart(id.color, gt, Value::string(kColors[1]));
    g.set_subpart(id.color, gb, Value::string(kColors[0]));
    for (Part p : {gt, gb}) {
        g.set_subpart(id.clear, p, g.add_var(id.clear_t));
        g.set_subpart(id.table, p, g.add_var(id.table_t));
    }
    Part o = g.add_part(id.on, "o");
    g.set_subpart(id.on_l, o, gt);
    g.set_subpart(id.on_r, o, gb);

    auto p = std::make_shared<plan::Problem>();
    p->name = "Generated" + std::to_string(n);
    p->domain = domain;
    p->initial = std::make_shared<const ACSet>(std::move(x));
    p->goal = std::make_shared<const ACSet>(std::move(g));
    return p;
}

// `steps` steps of unstack/putdown/pickup/stack cycles over towers 2, 3, ... of n blocks.
plan::Plan generated_plan(std::size_t n, std::size_t steps) {
    const std::size_t towers = n / 2;
    plan::Plan out;
    out.steps.reserve(steps);
    for (std::size_t i = 0; i < steps; ++i) {
        std::size_t tower = 1 + (i / 4) % (towers - 1); // 0-based; tower 0 is the goal's
        std::string top = block_name(2 * tower + 1), below = block_name(2 * tower);
        switch (i % 4) {
        case 0:
            out.steps.push_back({"unstack", {top, below}, {}});
            break;
        case 1:
            out.steps.push_back({"putdown", {top}, {}});
            break;
        case 2:
            out.steps.push_back({"pickup", {top}, {}});
            break;
        default:
            out.steps.push_back({"stack", {top, below}, {}});
            break;
        }
    }
    return out;
}

void run_generated(benchmark::State& state, bool use_delta, std::size_t n, std::size_t steps) {
    const auto& f = inputs().along(use_delta);
    auto problem = generated_problem(n);
    auto plan = generated_plan(n, steps);
    double migrate_ms = 0, apply_ms = 0, validate_ms = 0, total_ms = 0;
    std::size_t parts = 0;
    for (auto _ : state) {
        auto t = transfer::transfer_plan(f, *problem, plan);
        check(t, steps);
        migrate_ms += t.timings.migrate_ms;
        apply_ms += t.timings.apply_ms;
        validate_ms += t.timings.validate_ms;
        total_ms += t.timings.total_ms;
        parts = t.target_initial->total_parts();
        benchmark::DoNotOptimize(t);
    }
    const auto iters = static_cast<double>(state.iterations());
    const auto k = static_cast<double>(steps);
    state.counters["us_per_step"] = 1000 * total_ms / iters / k;
    state.counters["apply_us_per_step"] = 1000 * apply_ms / iters / k;
    state.counters["migrate_ms"] = migrate_ms / iters;
    state.counters["validate_ms"] = validate_ms / iters;
    state.counters["parts"] = static_cast<double>(parts);
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(steps));
}

constexpr std::size_t kLengthBlocks = 100;
constexpr std::int64_t kSizeSteps = 100;
constexpr std::int64_t kLongSteps = 10'000;

void BM_TransferPlanLength(benchmark::State& state, bool use_delta) {
    run_generated(state, use_delta, kLengthBlocks, static_cast<std::size_t>(state.range(0)));
}

void BM_TransferStateSize(benchmark::State& state, bool use_delta) {
    run_generated(state, use_delta, static_cast<std::size_t>(state.range(0)),
                  static_cast<std::size_t>(state.range(1)));
}

BENCHMARK_CAPTURE(BM_TransferPlanLength, conjunctive, false)
    ->RangeMultiplier(10)
    ->Range(10, 10'000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TransferPlanLength, delta, true)
    ->RangeMultiplier(10)
    ->Range(10, 10'000)
    ->Unit(benchmark::kMillisecond);
// Blocks x steps: the fixed-length plan, and a long one, whose difference is the marginal cost
// of a step on a state of that size (without the once-per-transfer costs).
const std::vector<std::int64_t> kSizes = {10, 100, 1000, 10'000, 100'000};
BENCHMARK_CAPTURE(BM_TransferStateSize, conjunctive, false)
    ->ArgsProduct({kSizes, {kSizeSteps, kLongSteps}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_TransferStateSize, delta, true)
    ->ArgsProduct({kSizes, {kSizeSteps, kLongSteps}})
    ->Unit(benchmark::kMillisecond);

} // namespace
} // namespace catplan

BENCHMARK_MAIN();
