#include "catplan/transfer/transfer.hpp"

#include "catplan/migrate/migration.hpp"
#include "catplan/plan/validate.hpp"
#include "catplan/rewrite/dpo.hpp"
#include "catplan/transfer/rename.hpp"

#include <chrono>
#include <fmt/format.h>
#include <sys/resource.h>
#include <unordered_map>

namespace catplan::transfer {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Per object of a state: name -> the part with that name, or kNoPart when several share it.
class NameIndex {
public:
    explicit NameIndex(const ACSet& y) : by_ob_(y.schema().num_obs()) {
        for (std::uint32_t o = 0; o < by_ob_.size(); ++o) {
            for (Part p = 0; p < y.num_parts(ObId(o)); ++p) {
                std::string_view n = y.part_name(ObId(o), p);
                if (n.empty()) {
                    continue;
                }
                auto [it, fresh] = by_ob_[o].emplace(std::string(n), p);
                if (!fresh) {
                    it->second = kNoPart;
                }
            }
        }
    }

    /// The only part of ob with this name, or kNoPart.
    Part find(ObId ob, std::string_view name) const {
        auto it = by_ob_[ob.index()].find(std::string(name));
        return it == by_ob_[ob.index()].end() ? kNoPart : it->second;
    }

private:
    std::vector<std::unordered_map<std::string, Part>> by_ob_;
};

// The source object and part of L that the tuple at part p of Δ_F(L) (target object c) starts
// at, found through the tuple's name; nullopt when the tuple has no name.
std::optional<std::pair<ObId, Part>> tuple_origin(const SchemaMap& f, const ACSet& l,
                                                  const ACSet& fl, ObId c, Part p) {
    std::string_view name = fl.part_name(c, p);
    if (name.empty()) {
        return std::nullopt;
    }
    const auto& q = f.query(c);
    for (std::size_t i = 0; i < q.nodes().size(); ++i) {
        if (q.nodes()[i].is_value) {
            continue;
        }
        ObId ob = q.locate_node(i).ob;
        if (auto part = l.find_part(ob, name)) {
            return std::pair{ob, *part};
        }
        return std::nullopt;
    }
    return std::nullopt;
}

// The target match's parts fixed by carrying the source match through part names.
std::vector<hom::PartBinding> carried_bindings(const SchemaMap& f, const rewrite::Rule& rule,
                                               const rewrite::Rule& target_rule,
                                               const ACSetMorphism& m, const ACSet& x,
                                               const NameIndex& y_names, const Renaming& renaming) {
    std::vector<hom::PartBinding> out;
    const ACSet& fl = target_rule.L;
    for (std::uint32_t c = 0; c < fl.schema().num_obs(); ++c) {
        for (Part p = 0; p < fl.num_parts(ObId(c)); ++p) {
            auto origin = tuple_origin(f, rule.L, fl, ObId(c), p);
            if (!origin) {
                continue;
            }
            Part in_x = m.components[origin->first.index()][origin->second];
            std::string_view name = x.part_name(origin->first, in_x);
            if (name.empty()) {
                continue;
            }
            Part in_y = y_names.find(ObId(c), renamed(renaming, name));
            if (in_y != kNoPart) {
                out.push_back({ObId(c), p, in_y});
            }
        }
    }
    return out;
}

// The step `rule(args)` of a match: one argument per distinct parameter name.
plan::Step step_of(const rewrite::Rule& rule, const ACSetMorphism& m, const ACSet& y) {
    plan::Step step;
    step.action = rule.name;
    std::vector<std::string_view> seen;
    for (const auto& p : rule.parameters) {
        if (std::find(seen.begin(), seen.end(), p.name) != seen.end()) {
            continue;
        }
        seen.push_back(p.name);
        step.args.push_back(y.part_label(p.ob, m.components[p.ob.index()][p.part]));
    }
    return step;
}

// The parameter names of rule that target_rule does not have.
std::vector<std::string> lost_parameters(const rewrite::Rule& rule,
                                         const rewrite::Rule& target_rule) {
    std::vector<std::string> out;
    for (const auto& p : rule.parameters) {
        bool kept = std::any_of(target_rule.parameters.begin(), target_rule.parameters.end(),
                                [&](const auto& q) { return q.name == p.name; });
        if (!kept) {
            out.push_back(p.name);
        }
    }
    return out;
}

// Why rule has no match in y extending the bindings.
std::string explain_no_match(const rewrite::Rule& rule, const ACSet& y,
                             const std::vector<hom::PartBinding>& bindings) {
    hom::HomSearchOptions opt;
    opt.monic_all = true;
    opt.initial = bindings;
    opt.max_results = 1;
    auto embedding = hom::find_homomorphism(rule.L, y, opt);
    if (embedding) {
        auto why = rewrite::match_problem(rule, y, *embedding);
        return fmt::format("no valid match in the target: {}",
                           why ? *why : std::string("the match is rejected"));
    }
    auto missing = plan::explain_no_embedding(rule.L, y, bindings);
    return fmt::format("no match in the target: {}",
                       missing ? *missing : std::string("the precondition does not embed"));
}

struct Context {
    const SchemaMap& f;
    const plan::Validation& source;
    const plan::Plan& plan;
    const plan::Domain& source_domain;
    TransferResult& out;
    Renaming renaming; // source names -> target names (empty unless renaming by type)
};

// Applies the migrated action of step i to y; false (with failed_step set) when it cannot.
bool transfer_step(Context& cx, std::size_t i, const ACSet& x, ACSet& y) {
    const plan::Step& s = cx.plan.steps[i];
    const rewrite::Rule* rule = cx.source_domain.find_rule(s.action);
    const rewrite::Rule* target_rule = cx.out.target_domain.domain->find_rule(s.action);
    auto fail_at = [&](std::string why) {
        cx.out.failed_step = FailedStep{i, why};
        cx.out.reason = fmt::format("step {} {}: {}", i + 1, s.to_string(), why);
        return false;
    };
    if (target_rule == nullptr) {
        for (const auto& [name, why] : cx.out.target_domain.failures) {
            if (name == s.action) {
                return fail_at("the action does not migrate: " + why);
            }
        }
        return fail_at("the action does not migrate");
    }
    const ACSetMorphism& m = cx.source.matches[i];
    auto bindings = carried_bindings(cx.f, *rule, *target_rule, m, x, NameIndex(y), cx.renaming);
    rewrite::MatchOptions opt;
    opt.initial = bindings;
    opt.max_results = 1;
    auto matches = rewrite::find_matches(*target_rule, y, opt);
    if (matches.empty()) {
        return fail_at(explain_no_match(*target_rule, y, bindings));
    }
    StepTransfer st;
    st.source = s;
    st.target = step_of(*target_rule, matches[0], y);
    st.source_match = m;
    st.source_bindings = plan::describe_match(m, rule->L, x);
    st.target_bindings = plan::describe_match(matches[0], target_rule->L, y);
    st.lost_parameters = lost_parameters(*rule, *target_rule);
    auto applied = rewrite::rewrite_in_place(*target_rule, y, matches[0]);
    if (!applied) {
        return fail_at(applied.error());
    }
    st.target_match = std::move(matches[0]);
    cx.out.steps.push_back(std::move(st));
    return true;
}

void check_goal(TransferResult& out, const ACSet& y) {
    auto t0 = Clock::now();
    auto embedding = plan::embed_goal(*out.target_goal, y);
    out.goal_reached = static_cast<bool>(embedding);
    if (out.goal_reached) {
        out.goal.total = goal_statements(*out.target_goal).size();
        out.goal.satisfied = out.goal.total;
    } else {
        out.goal = goal_satisfaction(*out.target_goal, y);
    }
    if (!out.failed_step) {
        out.valid = out.goal_reached;
        if (!out.goal_reached) {
            out.reason = "goal not reached: " + embedding.error();
        }
    }
    out.timings.validate_ms = ms_since(t0);
}

} // namespace

std::string_view to_string(MigrationKind kind) {
    return kind == MigrationKind::Delta ? "delta" : "conjunctive";
}

MigratedDomain migrate_domain(const SchemaMap& f, const plan::Domain& d, std::string name) {
    auto domain = std::make_shared<plan::Domain>();
    domain->name = name.empty() ? fmt::format("{}_{}", d.name, f.target()->name()) : name;
    domain->schema = f.target();
    domain->range = d.range;
    MigratedDomain out;
    for (const auto& rule : d.rules) {
        auto migrated = migrate::migrate(f, *rule);
        if (migrated) {
            domain->rules.push_back(std::make_shared<rewrite::Rule>(std::move(*migrated)));
        } else {
            out.failures.emplace_back(rule->name, migrated.error());
        }
    }
    out.domain = std::move(domain);
    return out;
}

TransferResult transfer_plan(const SchemaMap& f, const plan::Problem& problem,
                             const plan::Plan& plan, const TransferOptions& options) {
    CATPLAN_ASSERT(f.ok(), "transfer along an unfinished or invalid map");
    auto t_total = Clock::now();
    TransferResult out;
    out.migration = f.is_delta() ? MigrationKind::Delta : MigrationKind::Conjunctive;

    auto t0 = Clock::now();
    plan::ValidateOptions vopt;
    vopt.keep_states = true;
    plan::Validation source = plan::validate_plan(problem, plan, vopt);
    out.source_valid = source.valid;
    out.source_reason = source.reason;
    out.timings.replay_ms = ms_since(t0);

    t0 = Clock::now();
    out.target_domain = migrate_domain(f, *problem.domain);
    ACSet y0 = migrate::migrate(f, *problem.initial);
    Renaming renaming;
    if (options.rename_by_type) {
        renaming = names_by_type(y0);
        rename_parts(y0, renaming);
    }
    out.target_initial = std::make_shared<const ACSet>(std::move(y0));
    out.target_goal = std::make_shared<const ACSet>(migrate::migrate(f, *problem.goal));
    out.timings.migrate_ms = ms_since(t0);

    t0 = Clock::now();
    ACSet y = *out.target_initial;
    if (options.keep_states) {
        out.target_states.push_back(y);
    }
    Context cx{f, source, plan, *problem.domain, out, std::move(renaming)};
    // Only the steps the source plan could take are transferred.
    std::size_t n = source.matches.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (!transfer_step(cx, i, source.states[i], y)) {
            break;
        }
        if (options.keep_states) {
            out.target_states.push_back(y);
        }
    }
    if (!out.failed_step && !source.valid && source.failed_step) {
        out.failed_step = FailedStep{*source.failed_step, "the source plan fails here"};
        out.reason = "the source plan is invalid: " + source.reason;
    }
    out.timings.apply_ms = ms_since(t0);

    check_goal(out, y);
    if (!source.valid && out.reason.empty()) {
        out.reason = "the source plan is invalid: " + source.reason;
        out.valid = false;
    }
    if (options.keep_states) {
        out.source_states = std::move(source.states);
        out.source_states.resize(out.steps.size() + 1, ACSet(problem.initial->schema_ptr()));
    }
    out.final_state = std::move(y);
    out.timings.total_ms = ms_since(t_total);
    return out;
}

plan::Step collapse_arguments(const rewrite::Rule& rule, const plan::Step& step) {
    plan::Step out;
    out.action = step.action;
    out.range = step.range;
    std::vector<std::string_view> seen;
    for (std::size_t i = 0; i < rule.parameters.size() && i < step.args.size(); ++i) {
        const auto& name = rule.parameters[i].name;
        if (std::find(seen.begin(), seen.end(), name) == seen.end()) {
            seen.push_back(name);
            out.args.push_back(step.args[i]);
        }
    }
    return out;
}

std::size_t edit_distance(const std::vector<plan::Step>& a, const std::vector<plan::Step>& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            bool same = a[i - 1].action == b[j - 1].action && a[i - 1].args == b[j - 1].args;
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

long peak_rss_kib() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) {
        return 0;
    }
    return usage.ru_maxrss;
}

Replan replan(const TransferResult& t, const plan::SearchOptions& options) {
    CATPLAN_ASSERT(t.target_domain.domain && t.target_initial && t.target_goal,
                   "replan needs a transfer's target problem");
    plan::Problem problem;
    problem.name = "replan";
    problem.domain = t.target_domain.domain;
    problem.initial = t.target_initial;
    problem.goal = t.target_goal;
    Replan out;
    auto t0 = Clock::now();
    out.search = plan::find_plan(problem, options);
    out.ms = ms_since(t0);
    out.peak_rss_kib = peak_rss_kib();
    if (out.search.plan) {
        for (const auto& s : out.search.plan->steps) {
            const auto* rule = problem.domain->find_rule(s.action);
            out.steps.push_back(rule ? collapse_arguments(*rule, s) : s);
        }
    }
    std::vector<plan::Step> transferred;
    for (const auto& s : t.steps) {
        transferred.push_back(s.target);
    }
    out.edit_distance = edit_distance(transferred, out.steps);
    return out;
}

} // namespace catplan::transfer
