#include "catplan/plan/costs.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/plan/actions.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <limits>
#include <memory>

namespace catplan::plan {

namespace {

/// Whether a term of c reads a parameter a migration lost (an argument neither a parameter nor
/// a part name).
bool reads_lost_parameter(const rewrite::Cost& c) {
    return std::any_of(c.terms.begin(), c.terms.end(), [](const rewrite::Cost::Term& t) {
        return std::any_of(t.arguments.begin(), t.arguments.end(),
                           [](const auto& a) { return a.parameter < 0 && a.constant.empty(); });
    });
}

} // namespace

FunctionTable::FunctionTable(const std::vector<FunctionValue>& values) {
    for (const auto& v : values) {
        values_.emplace(std::pair(v.function, v.args), v.value);
    }
}

std::optional<std::int64_t> FunctionTable::value(const std::string& f,
                                                 const std::vector<std::string>& args) const {
    auto it = values_.find(std::pair(f, args));
    return it == values_.end() ? std::nullopt : std::optional(it->second);
}

std::optional<std::int64_t> rule_cost(const Rule& rule, const std::vector<std::string>& args,
                                      const FunctionTable& table) {
    if (!rule.cost) {
        return 1;
    }
    std::int64_t total = rule.cost->constant;
    std::vector<std::string> at;
    for (const auto& term : rule.cost->terms) {
        at.clear();
        for (const auto& a : term.arguments) {
            if (a.parameter < 0 && a.constant.empty()) {
                return std::nullopt; // a parameter a migration lost
            }
            auto i = static_cast<std::size_t>(a.parameter);
            at.push_back(a.parameter < 0 ? a.constant : i < args.size() ? args[i] : "");
        }
        auto v = table.value(term.function, at);
        if (!v) {
            return std::nullopt;
        }
        total = add_cost(total, *v);
    }
    return total;
}

Result<std::int64_t> step_cost(const Problem& p, const Rule& rule,
                               const std::vector<std::string>& args) {
    if (!p.step_cost) {
        return std::int64_t{1};
    }
    if (auto c = p.step_cost(rule, args)) {
        return *c;
    }
    std::string what = rule.cost ? rule.cost->to_string(args) : "";
    if (rule.cost && reads_lost_parameter(*rule.cost)) {
        return fail(fmt::format("its cost {} reads a parameter its migration lost", what));
    }
    return fail(fmt::format("its cost {} has no value in the problem", what));
}

std::int64_t add_cost(std::int64_t a, std::int64_t b) {
    std::int64_t sum = 0;
    return __builtin_add_overflow(a, b, &sum) ? std::numeric_limits<std::int64_t>::max() : sum;
}

Result<std::int64_t> plan_cost(const Problem& p, const std::vector<Step>& steps) {
    CATPLAN_ASSERT(p.step_cost != nullptr, "the cost of a plan of a problem that sums costs");
    std::int64_t total = 0;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const Rule* rule = p.domain->find_rule(steps[i].action);
        CATPLAN_ASSERT(rule != nullptr, "a plan's steps name the domain's rules");
        auto c = step_cost(p, *rule, steps[i].args);
        if (!c) {
            return fail(fmt::format("step {} {}: {}", i + 1, describe_step(*p.domain, steps[i]),
                                    c.error()));
        }
        total = add_cost(total, *c);
    }
    return total;
}

bool has_costs(const Domain& domain) {
    return std::any_of(domain.rules.begin(), domain.rules.end(),
                       [](const auto& r) { return r->cost.has_value(); });
}

void set_step_cost(Problem& p) {
    if (p.counts_steps || !p.domain || !has_costs(*p.domain)) {
        p.step_cost = {};
        return;
    }
    auto table = std::make_shared<const FunctionTable>(p.values);
    p.step_cost = [table](const Rule& rule, const std::vector<std::string>& args) {
        return rule_cost(rule, args, *table);
    };
}

} // namespace catplan::plan
