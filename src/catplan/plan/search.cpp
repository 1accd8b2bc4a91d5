#include "catplan/plan/search.hpp"

#include "catplan/plan/cset_search.hpp"
#include "catplan/plan/ground/ground_search.hpp"

#include <fmt/format.h>

namespace catplan::plan {

std::optional<SearchKind> parse_search(std::string_view name) {
    if (name == "bfs") {
        return SearchKind::BreadthFirst;
    }
    if (name == "astar") {
        return SearchKind::AStar;
    }
    if (name == "gbfs") {
        return SearchKind::GreedyBestFirst;
    }
    if (name == "lazy") {
        return SearchKind::LazyGreedy;
    }
    if (name == "lama") {
        return SearchKind::Lama;
    }
    return std::nullopt;
}

std::string_view to_string(SearchKind kind) {
    switch (kind) {
    case SearchKind::BreadthFirst:
        return "bfs";
    case SearchKind::AStar:
        return "astar";
    case SearchKind::GreedyBestFirst:
        return "gbfs";
    case SearchKind::LazyGreedy:
        return "lazy";
    case SearchKind::Lama:
        return "lama";
    }
    CATPLAN_UNREACHABLE("search kind");
}

namespace {

double per_second(std::uint64_t count, double seconds) {
    return seconds > 0 ? static_cast<double>(count) / seconds : 0;
}

double megabytes(std::size_t bytes) {
    return static_cast<double>(bytes) / 1e6;
}

} // namespace

std::string describe(const SearchStats& st, bool timing, std::string_view prefix) {
    std::string text =
        fmt::format("{}expanded {}, evaluated {}, generated {}, duplicates {}, states {}", prefix,
                    st.expanded, st.evaluated, st.generated, st.duplicates, st.states);
    for (std::size_t i = 0; i < st.initial_h.size(); ++i) {
        const auto& [kind, value] = st.initial_h[i];
        text += fmt::format("{} {} {}", i == 0 ? "; initial state:" : ",", to_string(kind),
                            value ? std::to_string(*value) : std::string("dead end"));
    }
    text += '\n';
    if (timing) {
        double search = st.search_seconds();
        text += fmt::format(
            "{}time {:.3f} s (set-up {:.3f} s, search {:.3f} s; CPU {:.3f} s, search {:.3f} s), "
            "{:.0f} expanded/s, {:.0f} evaluated/s, memory {:.1f} MB (peak {:.1f} MB, {:.1f} MB "
            "after the set-up)\n",
            prefix, st.seconds, st.setup_seconds, search, st.cpu_seconds, st.search_cpu_seconds(),
            per_second(st.expanded, search), per_second(st.evaluated, search), megabytes(st.memory),
            megabytes(st.peak_memory), megabytes(st.setup_memory));
    }
    return text;
}

Limits SearchOptions::limits() const {
    std::size_t bytes = max_bytes == 0 ? default_memory_limit_bytes() : max_bytes;
    return {max_nodes, max_seconds, bytes == SIZE_MAX ? 0 : bytes};
}

namespace {

// The C-set search's nearest configuration to one it lacks, and the note saying so.
std::pair<SearchOptions, std::string> cset_options(const SearchOptions& o) {
    SearchOptions c = o;
    std::string note;
    if (o.search == SearchKind::LazyGreedy || o.search == SearchKind::Lama) {
        c.search = SearchKind::GreedyBestFirst;
        note = "greedy best-first in place of lazy search";
        if (o.search == SearchKind::Lama) {
            c.heuristic = HeuristicKind::HFF;
        }
    }
    if (c.heuristic == HeuristicKind::LmCut) {
        c.heuristic = HeuristicKind::HMax;
        note += std::string(note.empty() ? "" : ", ") + "hmax in place of lmcut";
    } else if (c.heuristic == HeuristicKind::LmCount) {
        c.heuristic = HeuristicKind::HFF;
        note += std::string(note.empty() ? "" : ", ") + "hff in place of lmcount";
    } else if (c.heuristic == HeuristicKind::Default) {
        c.heuristic = c.search == SearchKind::AStar ? HeuristicKind::Blind : HeuristicKind::HFF;
    }
    return {c, note};
}

std::string describe_cset(const SearchOptions& c) {
    switch (c.search) {
    case SearchKind::BreadthFirst:
        return "breadth-first";
    case SearchKind::AStar:
        return fmt::format("A*, {}", to_string(c.heuristic));
    default:
        return fmt::format("eager greedy best-first, {}", to_string(c.heuristic));
    }
}

SearchResult run_cset(const Problem& problem, const SearchOptions& options, Budget& budget,
                      std::string reason) {
    auto [c, note] = cset_options(options);
    SearchResult r = cset_search(problem, c, budget);
    r.path = "C-set";
    r.path_reason = std::move(reason);
    r.config = describe_cset(c) + (note.empty() ? "" : " (" + note + ")");
    r.optimal = r.status == SearchStatus::Solved &&
                (c.search == SearchKind::BreadthFirst ||
                 (c.search == SearchKind::AStar && c.heuristic == HeuristicKind::Blind));
    return r;
}

} // namespace

SearchResult find_plan(const Problem& problem, const SearchOptions& options) {
    CATPLAN_ASSERT(problem.initial != nullptr && problem.domain != nullptr,
                   "a problem needs an initial state and a domain");
    Budget budget(options.limits(), options.start.value_or(Clock::now()));
    if (!options.ground) {
        return run_cset(problem, options, budget, "the grounded search is turned off");
    }
    // The task refers to the problem for its lifetime, which ends within this call.
    ProblemPtr view(std::shared_ptr<const Problem>(), &problem);
    auto g = ground::ground_search(view, options, budget);
    if (!g.compiled) {
        return run_cset(problem, options, budget,
                        "the grounded search does not apply: " + g.why_not);
    }
    auto& r = g.result;
    if (!g.rejected.empty()) {
        return run_cset(problem, options, budget,
                        "the grounded plan was rejected (a bug; please report it): " + g.rejected);
    }
    if (r.status == SearchStatus::Unsolvable && r.exits > 0) {
        auto c = run_cset(problem, options, budget,
                          fmt::format("the grounded search found no plan but left out {} "
                                      "transitions it cannot represent ({})",
                                      r.exits, r.exit_example));
        c.stats.ground_seconds = r.stats.ground_seconds;
        return c;
    }
    return std::move(r);
}

} // namespace catplan::plan
