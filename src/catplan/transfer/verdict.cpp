#include "catplan/transfer/verdict.hpp"

#include "catplan/base/assert.hpp"

#include <algorithm>

namespace catplan::transfer {

std::string Fault::to_string() const {
    return where.empty() ? why : where + ": " + why;
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
    if (faults.empty() || !faults.front().step) {
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

} // namespace catplan::transfer
