#include "catplan/transfer/verdict.hpp"

#include "catplan/base/assert.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace catplan::transfer {

std::string Fault::to_string() const {
    return where.empty() ? why : where + ": " + why;
}

Fault Fault::from_reason(Kind kind, std::optional<std::size_t> step, std::string where,
                         const std::string& reason) {
    if (!where.empty() && reason.rfind(where + ": ", 0) == 0) {
        std::string why = reason.substr(where.size() + 2);
        return {kind, step, std::move(where), std::move(why)};
    }
    return {kind, step, {}, reason};
}

bool Claim::holds() const {
    return failing() == nullptr;
}

const Hypothesis* Claim::failing() const {
    auto it = std::find_if(hypotheses.begin(), hypotheses.end(),
                           [](const Hypothesis& h) { return !h.holds; });
    return it == hypotheses.end() ? nullptr : &*it;
}

std::string headline(const Fault& fault) {
    return fault.kind == Fault::Kind::SourcePlan
               ? "the source plan is invalid: " + fault.to_string()
               : fault.to_string();
}

std::string Verdict::reason() const {
    return faults.empty() ? std::string() : headline(faults.front());
}

const Fault* Verdict::find(Fault::Kind kind) const {
    auto it =
        std::find_if(faults.begin(), faults.end(), [&](const Fault& f) { return f.kind == kind; });
    return it == faults.end() ? nullptr : &*it;
}

const Fault* Verdict::failed_step() const {
    // The replay stops at most once, and that fault comes first.
    if (faults.empty() || !faults.front().step || faults.front().kind == Fault::Kind::Divergence) {
        return nullptr;
    }
    return &faults.front();
}

const Claim& Verdict::claim(Claim::Kind kind) const {
    auto it =
        std::find_if(claims.begin(), claims.end(), [&](const Claim& c) { return c.kind == kind; });
    CATPLAN_ASSERT(it != claims.end(), "a verdict holds every kind of claim");
    return *it;
}

std::string Verdict::summary() const {
    if (!valid()) {
        return "invalid: " + reason();
    }
    const Divergence* d = diverged();
    if (d == nullptr) {
        return "valid: every step applies and the goal embeds monically";
    }
    if (trajectory == Trajectory::FollowSource) {
        return fmt::format("valid state by state, but {} target step(s) do not reach Δ_F of the "
                           "source state (the first: {})",
                           divergences.size(), d->where);
    }
    return fmt::format("valid in the target domain, but not the migration of the source plan: "
                       "the target states diverge from Δ_F of the source states after {}",
                       d->where);
}

namespace {

// "Linen l1" or "Linen l1, Crate c2 and 3 more".
std::string listed(const std::vector<std::string>& items, std::size_t more) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        bool last = i + 1 == items.size() && more == 0;
        out += i == 0 ? "" : (last ? " and " : ", ");
        out += items[i];
    }
    if (more > 0) {
        out += fmt::format(" and {} more", more);
    }
    return out;
}

} // namespace

std::string Divergence::difference() const {
    std::string state = fmt::format("Δ_F(X{})", step + 1);
    std::size_t more_target = only_in_migrated.empty() ? more : 0;
    std::size_t more_migrated = only_in_migrated.empty() ? 0 : more;
    std::string out;
    if (!only_in_target.empty()) {
        out +=
            fmt::format("it has {}, which {} has not", listed(only_in_target, more_target), state);
    }
    if (!only_in_migrated.empty()) {
        out += fmt::format("{}{} has {}, which it has not", out.empty() ? "" : "; ", state,
                           listed(only_in_migrated, more_migrated));
    }
    if (out.empty()) {
        out = "they make the same statements but are not isomorphic (they differ in which "
              "unknown values are shared)";
    }
    return out;
}

std::string Divergence::to_string() const {
    return fmt::format("the target state after {} is not Δ_F(X{}): {}", where, step + 1,
                       difference());
}

} // namespace catplan::transfer
