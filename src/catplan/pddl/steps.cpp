#include "catplan/pddl/steps.hpp"

#include "catplan/plan/actions.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>

namespace catplan::pddl {

plan::Plan rule_plan(const Import& im, const IpcPlan& plan) {
    plan::Plan steps;
    for (const auto& s : plan) {
        steps.steps.push_back(plan::Step{s.action, s.args, s.range});
    }
    return plan::rule_plan(*im.domain, *im.problem->initial, steps);
}

namespace {

/// The facts of n.n_state outside the image of n : goal -> N, as ground atoms.
std::vector<Atom> added_facts(const Import& im, const rewrite::ApplicationCondition& c) {
    std::vector<Atom> out;
    const acset::ACSet& x = c.n_state;
    for (const auto& pred : im.pddl_domain.predicates) {
        ObId ob = im.predicate_ob.at(pred.name);
        const auto& image = c.n.components[ob.index()];
        const auto& homs = im.predicate_homs.at(pred.name);
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            if (std::find(image.begin(), image.end(), p) != image.end()) {
                continue;
            }
            Atom a{pred.name, {}, {}};
            for (HomId h : homs) {
                Part q = x.subpart(h, p);
                ObId type = x.schema().hom(h).codom;
                a.args.push_back(
                    {q == kNoPart ? "?" : std::string(x.part_name(type, q)), false, {}});
            }
            out.push_back(std::move(a));
        }
    }
    return out;
}

} // namespace

Problem problem_of(const Import& im, std::string name, const acset::ACSet& initial,
                   const acset::ACSet& goal,
                   const std::vector<rewrite::ApplicationCondition>& conditions) {
    Problem p;
    p.name = std::move(name);
    p.domain_name = im.pddl_domain.name;
    // Types are listed parents first, so the last type a name is seen at is its most specific.
    std::map<std::string, std::string> type_of;
    std::vector<std::string> order;
    for (const auto& t : im.pddl_domain.types) {
        ObId ob = im.type_ob.at(t.name);
        for (Part q = 0; q < initial.num_parts(ob); ++q) {
            std::string n(initial.part_name(ob, q));
            if (type_of.emplace(n, t.name).second) {
                order.push_back(n);
            } else {
                type_of[n] = t.name;
            }
        }
    }
    for (const auto& n : order) {
        bool constant =
            std::any_of(im.pddl_domain.constants.begin(), im.pddl_domain.constants.end(),
                        [&](const TypedName& c) { return c.name == n; });
        if (!constant) {
            p.objects.push_back({n, type_of[n], {}});
        }
    }
    p.init = im.facts(initial);
    for (auto& a : im.facts(goal)) {
        p.goal.push_back({std::move(a), true, {}});
    }
    // A condition that adds one fact is a negative goal; one that adds several would be a negated
    // conjunction, which PDDL's goals cannot say without :disjunctive-preconditions.
    for (const auto& c : conditions) {
        auto added = added_facts(im, c);
        if (c.negative && added.size() == 1) {
            p.goal.push_back({std::move(added[0]), false, {}});
        } else {
            ++p.unwritten_goal_conditions;
        }
    }
    p.metric = im.pddl_domain.has_costs();
    return p;
}

std::string write_problem(const Problem& p) {
    std::string out = fmt::format("(define (problem {})\n  (:domain {})\n", p.name, p.domain_name);
    out += "  (:objects";
    for (const auto& o : p.objects) {
        out += fmt::format(" {} - {}", o.name, o.type);
    }
    out += ")\n  (:init";
    for (const auto& a : p.init) {
        out += "\n    " + a.to_string();
    }
    if (p.metric && std::none_of(p.values.begin(), p.values.end(), [](const FunctionValue& v) {
            return v.term.predicate == "total-cost";
        })) {
        out += "\n    (= (total-cost) 0)";
    }
    for (const auto& v : p.values) {
        out += fmt::format("\n    (= {} {})", v.term.to_string(), v.value);
    }
    out += ")\n  (:goal (and";
    for (const auto& l : p.goal) {
        out += "\n    " + l.to_string();
    }
    return out + (p.metric ? "))\n  (:metric minimize (total-cost)))\n" : ")))\n");
}

} // namespace catplan::pddl
