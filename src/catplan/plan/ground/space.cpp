#include "catplan/plan/ground/space.hpp"

#include <algorithm>

namespace catplan::plan::ground {

Space::Space(const Task& t, Budget& budget, const SearchOptions& options, SearchStats& st,
             bool costs)
    : task(t),
      stats(st),
      budget_(budget),
      options_(options),
      costs_(costs),
      packer_(t),
      registry_(packer_, budget),
      generator_(t, packer_),
      scratch_(packer_.words()),
      last_report_(Clock::now()) {}

StateId Space::initial() {
    packer_.pack(task.initial, scratch_.data());
    auto ins = registry_.insert(scratch_.data());
    node(ins.id);
    return ins.id;
}

std::optional<StateRegistry::Insertion> Space::successor(StateId s, ActionId a) {
    if (!apply(task, packer_, registry_.state(s), a, scratch_.data())) {
        if (exits++ == 0) {
            const Action& act = task.actions[a];
            exit_example = task.describe_action(a) + ": " +
                           (act.exit.empty() ? "it would make a second, equal part" : act.exit);
        }
        return std::nullopt;
    }
    ++stats.generated;
    auto ins = registry_.insert(scratch_.data());
    if (!ins.is_new) {
        ++stats.duplicates;
    }
    stats.states = registry_.size();
    return ins;
}

const std::vector<std::uint32_t>& Space::values(StateId s) {
    packer_.unpack(registry_.state(s), values_);
    return values_;
}

std::vector<ActionId> Space::path_to(StateId s) {
    std::vector<ActionId> plan;
    for (StateId x = s; node(x).parent != kNone; x = node(x).parent) {
        plan.push_back(node(x).action);
    }
    std::reverse(plan.begin(), plan.end());
    return plan;
}

std::optional<SearchStatus> Space::limit_reached() {
    if (options_.max_nodes > 0 && stats.expanded >= options_.max_nodes) {
        return SearchStatus::NodeLimit;
    }
    auto stop = budget_.check();
    if (options_.progress && stats.expanded > 0) {
        auto now = Clock::now();
        if (std::chrono::duration<double>(now - last_report_).count() >=
            options_.progress_interval) {
            last_report_ = now;
            stats.seconds = budget_.elapsed();
            stats.memory = budget_.resident();
            stats.peak_memory = budget_.peak_bytes();
            options_.progress(stats);
        }
    }
    return stop;
}

} // namespace catplan::plan::ground
