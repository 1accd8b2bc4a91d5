// Rules and domains written back in the language (docs/language.md, "Rules" and "Domains and
// problems"). Every part of L, K, R and of each condition's N is written as a named generator, so
// the legs go by names alone and loading the text gives the same rule: the same states, legs,
// conditions, parameters, cost and facts.

#include "catplan/lang/detail/printing.hpp"
#include "catplan/lang/module.hpp"
#include "catplan/lang/syntax.hpp"
#include "catplan/plan/domain.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <set>

namespace catplan::lang {

using acset::ACSet;
using hom::ACSetMorphism;
using rewrite::Rule;
using schema::Schema;

namespace detail {

std::vector<std::vector<Part>> preimages(const ACSetMorphism& f, const ACSet& x, const ACSet& y) {
    std::vector<std::vector<Part>> pre(y.schema().num_obs());
    for (std::uint32_t o = 0; o < pre.size(); ++o) {
        pre[o].assign(y.num_parts(ObId(o)), kNoPart);
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            pre[o][f(ObId(o), p)] = p;
        }
    }
    return pre;
}

std::string block_statements(const BlockView& b, std::string_view indent) {
    const ACSet& x = *b.x;
    const Schema& s = x.schema();
    auto given = [&](std::uint32_t o, Part p) { return b.from == nullptr ? kNoPart : b.pre[o][p]; };
    std::string out;
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        std::vector<std::string> declared;
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            if (given(o, p) == kNoPart) {
                declared.push_back(quoted_name((*b.names)[o][p]));
            }
        }
        if (!declared.empty()) {
            std::string list = fmt::format("{}", fmt::join(declared, ", "));
            out += fmt::format("{}{}::{}\n", indent, declared.size() == 1 ? list : "(" + list + ")",
                               quoted_name(s.ob(ObId(o)).name));
        }
    }
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            Part q = given(o, p);
            const std::string pn = quoted_name((*b.names)[o][p]);
            for (HomId f : s.homs_from(ObId(o))) {
                Part t = x.subpart(f, p);
                if (t != kNoPart && (q == kNoPart || b.from->subpart(f, q) == kNoPart)) {
                    out += fmt::format("{}{}({}) == {}\n", indent, quoted_name(s.hom(f).name), pn,
                                       quoted_name((*b.names)[s.hom(f).codom.index()][t]));
                }
            }
            for (AttrId a : s.attrs_from(ObId(o))) {
                const auto& v = x.subpart(a, p);
                if (!v.is_unset() && (q == kNoPart || b.from->subpart(a, q).is_unset())) {
                    out += fmt::format("{}{}({}) == {}\n", indent, quoted_name(s.attr(a).name), pn,
                                       v.to_string());
                }
            }
        }
    }
    return out;
}

} // namespace detail

namespace {

using acset::ACSet;
using hom::ACSetMorphism;
using rewrite::Rule;
using schema::Schema;

using detail::BlockView;
using detail::NamePool;
using detail::PartNames;
using detail::preimages;

// L's names: the parameters first (the header names them), then the parts' own names.
Result<PartNames> l_names(const Rule& rule, NamePool& pool) {
    const ACSet& L = rule.L;
    PartNames names(L.schema().num_obs());
    for (std::uint32_t o = 0; o < names.size(); ++o) {
        names[o].resize(L.num_parts(ObId(o)));
    }
    for (const auto& p : rule.parameters) {
        std::string& slot = names[p.ob.index()][p.part];
        if (!slot.empty() || pool.used(p.name) ||
            p.name.find_first_of("\n\r") != std::string::npos) {
            return fail(fmt::format("its parameter '{}' cannot be written as a generator of its "
                                    "own",
                                    p.name));
        }
        slot = p.name;
        pool.add(p.name);
    }
    for (std::uint32_t o = 0; o < names.size(); ++o) {
        for (Part p = 0; p < names[o].size(); ++p) {
            if (names[o][p].empty()) {
                names[o][p] = pool.take(L.part_name(ObId(o), p), L.schema().ob(ObId(o)).name, p);
            }
        }
    }
    return names;
}

// y's names along f : x -> y: an image takes its preimage's name, another part a name of its own.
// f must be monic, or two of x's generators would have to be one.
Result<PartNames> names_along(const ACSetMorphism& f, const ACSet& x, const PartNames& xn,
                              const ACSet& y, NamePool& pool, std::string_view what) {
    const Schema& s = y.schema();
    PartNames names(s.num_obs());
    for (std::uint32_t o = 0; o < names.size(); ++o) {
        names[o].resize(y.num_parts(ObId(o)));
        for (Part p = 0; p < x.num_parts(ObId(o)); ++p) {
            std::string& slot = names[o][f(ObId(o), p)];
            if (!slot.empty()) {
                return fail(fmt::format("{} identifies two parts of {}", what, s.ob(ObId(o)).name));
            }
            slot = xn[o][p];
        }
        for (Part p = 0; p < names[o].size(); ++p) {
            if (names[o][p].empty()) {
                names[o][p] = pool.take(y.part_name(ObId(o), p), s.ob(ObId(o)).name, p);
            }
        }
    }
    return names;
}

std::string block(std::string_view name, const BlockView& b) {
    return fmt::format("    {} => begin\n{}    end\n", name, detail::block_statements(b, "      "));
}

// Why the language cannot write the rule exactly, or "" when it can.
std::string unwritable(const Rule& rule) {
    if (rule.semantics != rewrite::Semantics::DPO) {
        return "it deletes with single-pushout semantics";
    }
    for (const auto& per_type : rule.exprs) {
        for (const auto& e : per_type) {
            if (e) {
                return "it computes an attribute";
            }
        }
    }
    if (rule.cost) {
        for (const auto& t : rule.cost->terms) {
            for (const auto& a : t.arguments) {
                if (a.parameter < 0 && a.constant.empty()) {
                    return fmt::format("its cost reads {} of a parameter it lost", t.function);
                }
            }
        }
    }
    std::vector<const ACSet*> states = {&rule.L, &rule.K, &rule.R};
    for (const auto& c : rule.conditions) {
        states.push_back(&c.n_state);
    }
    const Schema& s = rule.L.schema();
    for (const ACSet* x : states) {
        for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
            if (x->num_vars(AttrTypeId(t)) != 0) {
                return "it has attribute variables";
            }
        }
    }
    // Eff gives a part it creates a new part for every hom it leaves unset.
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        for (Part p : rule.created_parts(ObId(o))) {
            for (HomId f : s.homs_from(ObId(o))) {
                if (rule.R.subpart(f, p) == kNoPart) {
                    return fmt::format("a part it creates leaves {} unset", s.hom(f).name);
                }
            }
        }
    }
    return "";
}

// An argument of an action or a cost term: the parameter's name or the part name in quotes.
std::string argument_text(const Rule& rule, const rewrite::ActionOf::Argument& a) {
    return a.parameter < 0
               ? acset::Value::string(a.constant).to_string()
               : quoted_name(rule.parameters[static_cast<std::size_t>(a.parameter)].name);
}

// `cost = 2 + road_length(from, to)`, when the rule says a cost.
std::string cost_statement(const Rule& rule) {
    if (!rule.cost) {
        return "";
    }
    std::vector<std::string> parts;
    if (rule.cost->constant != 0 || rule.cost->terms.empty()) {
        parts.push_back(std::to_string(rule.cost->constant));
    }
    for (const auto& t : rule.cost->terms) {
        std::vector<std::string> args;
        for (const auto& a : t.arguments) {
            args.push_back(argument_text(rule, a));
        }
        parts.push_back(fmt::format("{}({})", quoted_name(t.function), fmt::join(args, ", ")));
    }
    return fmt::format("    cost = {}\n", fmt::join(parts, " + "));
}

// `action = stack(x, x)`, unless the action is the rule itself.
std::string action_statement(const Rule& rule) {
    if (!rule.action) {
        return "";
    }
    std::vector<std::string> args;
    bool itself = rule.action->name == rule.name;
    for (std::size_t i = 0; i < rule.action->arguments.size(); ++i) {
        const auto& a = rule.action->arguments[i];
        itself = itself && a.parameter == static_cast<int>(i);
        args.push_back(argument_text(rule, a));
    }
    if (itself && args.size() == rule.parameters.size()) {
        return "";
    }
    return fmt::format("    action = {}({})\n", quoted_name(rule.action->name),
                       fmt::join(args, ", "));
}

} // namespace

Result<std::string> print_rule(const Rule& rule) {
    if (std::string why = unwritable(rule); !why.empty()) {
        return fail(fmt::format("rule '{}' cannot be written: {}", rule.name, why));
    }
    NamePool pool;
    auto ln = l_names(rule, pool);
    if (!ln) {
        return fail(fmt::format("rule '{}' cannot be written: {}", rule.name, ln.error()));
    }
    const Schema& s = rule.L.schema();
    PartNames kn(s.num_obs());
    for (std::uint32_t o = 0; o < kn.size(); ++o) {
        for (Part k = 0; k < rule.K.num_parts(ObId(o)); ++k) {
            kn[o].push_back((*ln)[o][rule.l(ObId(o), k)]);
        }
    }
    auto rn = names_along(rule.r, rule.K, kn, rule.R, pool, "r : Keep -> Eff");
    if (!rn) {
        return fail(fmt::format("rule '{}' cannot be written: {}", rule.name, rn.error()));
    }
    std::vector<std::string> params;
    for (const auto& p : rule.parameters) {
        params.push_back(quoted_name(p.name));
    }
    std::string out =
        fmt::format("  @rule {}({}) begin\n", quoted_name(rule.name), fmt::join(params, ", "));
    out += cost_statement(rule);
    out += action_statement(rule);
    out += block("Pre", BlockView{&rule.L, &*ln, nullptr, {}});
    out += block("Keep", BlockView{&rule.K, &kn, nullptr, {}});
    out += block("Eff", BlockView{&rule.R, &*rn, &rule.K, preimages(rule.r, rule.K, rule.R)});
    for (const auto& c : rule.conditions) {
        auto nn = names_along(c.n, rule.L, *ln, c.n_state, pool, "n : Pre -> N");
        if (!nn) {
            return fail(fmt::format("rule '{}' cannot be written: {}", rule.name, nn.error()));
        }
        out += block(c.negative ? "NAC" : "PAC",
                     BlockView{&c.n_state, &*nn, &rule.L, preimages(c.n, rule.L, c.n_state)});
    }
    return out + "  end\n";
}

Result<std::string> print_domain(const plan::Domain& d) {
    std::string out =
        fmt::format("@domain {}({}) begin\n", quoted_name(d.name), quoted_name(d.schema->name()));
    if (!d.rules.empty() && !d.rules[0]->relations.empty()) {
        std::vector<std::string> facts;
        for (ObId ob : d.rules[0]->relations) {
            facts.push_back(quoted_name(d.schema->ob(ob).name));
        }
        out += fmt::format("  facts = ({})\n", fmt::join(facts, ", "));
    }
    for (const auto& rule : d.rules) {
        if (rule->relations != d.rules[0]->relations) {
            return fail(fmt::format("rule '{}' has facts of its own, which a domain cannot say",
                                    rule->name));
        }
        auto text = print_rule(*rule);
        if (!text) {
            return text;
        }
        out += "\n" + *text;
    }
    return out + "end\n";
}

Result<std::string> print_problem(const plan::Problem& p, std::string_view domain,
                                  std::string_view initial, std::string_view goal,
                                  std::span<const ObId> name_first) {
    std::string out =
        fmt::format("@problem {}({}) begin\n  initial = {}\n  goal = {}\n", quoted_name(p.name),
                    quoted_name(domain), quoted_name(initial), quoted_name(goal));
    if (p.counts_steps) {
        out += "  metric = steps\n";
    }
    for (const auto& v : p.values) {
        std::vector<std::string> args;
        for (const auto& a : v.args) {
            args.push_back(quoted_name(a));
        }
        out +=
            fmt::format("  {}({}) = {}\n", quoted_name(v.function), fmt::join(args, ", "), v.value);
    }
    if (p.goal_conditions.empty()) {
        return out + "end\n";
    }
    const ACSet& g = *p.goal;
    auto names = detail::state_names(g, name_first);
    NamePool pool;
    for (const auto* table : {&names.parts, &names.vars}) {
        for (const auto& row : *table) {
            for (const auto& n : row) {
                pool.add(n);
            }
        }
    }
    for (const auto& c : p.goal_conditions) {
        auto pre = preimages(c.n, g, c.n_state);
        const Schema& s = g.schema();
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Part q = 0; q < c.n_state.num_parts(ObId(o)); ++q) {
                for (AttrId a : s.attrs_from(ObId(o))) {
                    if (pre[o][q] == kNoPart && c.n_state.subpart(a, q).is_var()) {
                        return fail(fmt::format("problem '{}' cannot be written: a part its goal "
                                                "condition adds has an unknown {}",
                                                p.name, s.attr(a).name));
                    }
                }
            }
        }
        auto nn = names_along(c.n, g, names.parts, c.n_state, pool, "n : goal -> N");
        if (!nn) {
            return fail(fmt::format("problem '{}' cannot be written: {}", p.name, nn.error()));
        }
        out += fmt::format(
            "  {} => begin\n{}  end\n", c.negative ? "NAC" : "PAC",
            detail::block_statements(BlockView{&c.n_state, &*nn, &g, std::move(pre)}, "    "));
    }
    return out + "end\n";
}

} // namespace catplan::lang
