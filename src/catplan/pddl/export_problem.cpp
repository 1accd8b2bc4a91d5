// The problem side of the export: the initial state, the goal (a PDDL goal or the action
// reach-goal), the files put together, and plans translated both ways (export.hpp).

#include "catplan/pddl/detail/export_writer.hpp"
#include "catplan/pddl/export.hpp"
#include "catplan/plan/costs.hpp"
#include "catplan/plan/validate.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <set>

namespace catplan::pddl {

namespace {

using detail::AttrUse;
using detail::NameSet;
using detail::Thing;
using detail::Things;
using detail::Writer;

std::string conjunction(const std::vector<std::string>& items) {
    if (items.size() == 1) {
        return items[0];
    }
    return fmt::format("(and {})", fmt::join(items, " "));
}

/// Whether a rule, a condition or the goal reads Bool attribute a as false.
bool read_as_false(const plan::Domain& d, const plan::Problem& p, AttrId a) {
    auto has_false = [&](const acset::ACSet& x) {
        for (Part q = 0; q < x.num_parts(x.schema().attr(a).dom); ++q) {
            if (x.subpart(a, q).is_concrete() && !x.subpart(a, q).as_bool()) {
                return true;
            }
        }
        return false;
    };
    for (const auto& r : d.rules) {
        if (has_false(r->L) || std::any_of(r->conditions.begin(), r->conditions.end(),
                                           [&](const auto& c) { return has_false(c.n_state); })) {
            return true;
        }
    }
    return has_false(*p.goal);
}

/// The initial state's facts; fails on two equal facts, two markers of a shape, or an unknown
/// Bool value that something reads as false (PDDL's closed world would make it false).
Result<std::vector<std::string>> initial_facts(Writer& w, const Things& things,
                                               const acset::ACSet& x) {
    const schema::Schema& s = x.schema();
    std::vector<std::string> out;
    std::set<std::string> seen, markers;
    auto term = [&](ObId ob, Part p) {
        const Thing& t = things.things[things.at(ob, p)];
        return detail::TermText{t.marker ? "" : t.name, t.shape};
    };
    for (const Thing& t : things.things) {
        if (t.marker) {
            if (!markers.insert(t.shape).second) {
                return fail(fmt::format("not expressible: the initial state has two markers {} "
                                        "(unnamed things rules create and delete); PDDL has room "
                                        "for one",
                                        t.shape));
            }
            out.push_back(fmt::format("({})", w.presence(t.shape)));
            continue;
        }
        for (std::size_t o = 0; o < t.part.size(); ++o) {
            if (t.part[o] != kNoPart && !w.rd.member_predicate[o].empty()) {
                out.push_back(fmt::format("({} {})", w.rd.member_predicate[o], t.name));
            }
        }
        for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
            Part p = t.part[s.attr(AttrId(a)).dom.index()];
            if (p != kNoPart && w.rd.attrs[a].use == AttrUse::Bool &&
                !x.subpart(AttrId(a), p).is_concrete() &&
                read_as_false(w.domain, *w.problem, AttrId(a))) {
                return fail(fmt::format("not expressible: {}({}) is unknown in the initial state, "
                                        "and PDDL would read it as false",
                                        s.attr(AttrId(a)).name, t.name));
            }
        }
        std::vector<std::pair<std::string, bool>> values;
        w.attr_facts(x, t, t.name, values);
        for (const auto& [f, v] : values) {
            if (v) {
                out.push_back(f);
            }
        }
    }
    for (ObId ob : w.rd.facts) {
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            auto f = w.atom(x, ob, p, term);
            if (!f) {
                return fail(f.error());
            }
            if (!seen.insert(*f).second) {
                return fail(fmt::format("not expressible: the initial state has two equal facts "
                                        "{} (PDDL facts are a set)",
                                        *f));
            }
            out.push_back(*f);
        }
    }
    return out;
}

/// The goal: its things, whether it is a pattern, and its statements.
struct GoalText {
    Things things;
    bool pattern = false;
    std::vector<std::string> terms;                          // by thing
    std::vector<std::string> statements;                     // atoms and negated atoms
    std::vector<std::pair<std::string, std::string>> params; // ?x, type
    std::vector<std::pair<ObId, Part>> param_parts;
    /// "d - City" per pinned thing: constants of the domain when the goal action names them.
    std::set<std::string> pinned;
};

Result<GoalText> read_goal(Writer& w, const acset::ACSet& g) {
    NameSet names;
    auto things = detail::find_things(w.rd, g, {}, names, "the goal");
    if (!things) {
        return fail(things.error());
    }
    GoalText gt{std::move(*things), false, {}, {}, {}, {}, {}};
    const schema::Schema& s = g.schema();
    for (const Thing& t : gt.things.things) {
        gt.pattern = gt.pattern || !t.pinned;
        gt.terms.push_back(t.pinned ? t.name : "?" + t.name);
        if (t.pinned) {
            gt.pinned.insert(t.name + " - " + detail::thing_type(w.rd, t));
        } else {
            gt.params.emplace_back("?" + t.name, detail::thing_type(w.rd, t));
            gt.param_parts.emplace_back(t.first, t.part[t.first.index()]);
        }
    }
    for (std::size_t i = 0; i < gt.things.things.size(); ++i) {
        const Thing& t = gt.things.things[i];
        for (std::size_t o = 0; o < t.part.size(); ++o) {
            if (t.part[o] != kNoPart && !w.rd.member_predicate[o].empty()) {
                gt.statements.push_back(
                    fmt::format("({} {})", w.rd.member_predicate[o], gt.terms[i]));
            }
        }
        std::vector<std::pair<std::string, bool>> values;
        w.attr_facts(g, t, gt.terms[i], values);
        for (const auto& [f, v] : values) {
            gt.pattern = gt.pattern || !v; // catplan's PDDL reader takes no negative goal
            gt.statements.push_back(v ? f : "(not " + f + ")");
        }
    }
    for (std::uint32_t a = 0; a < s.num_attrs(); ++a) {
        const auto& info = s.attr(AttrId(a));
        for (Part p = 0; p < g.num_parts(info.dom); ++p) {
            const auto& v = g.subpart(AttrId(a), p);
            if (w.rd.attrs[a].use != AttrUse::Name && v.is_var() &&
                g.var_incident(info.codom, v.var_index()).size() > 1) {
                return fail(fmt::format("not expressible: the goal asks two values of {} to be "
                                        "equal",
                                        info.name));
            }
        }
    }
    auto term = [&](ObId ob, Part p) {
        return detail::TermText{gt.terms[gt.things.at(ob, p)], ""};
    };
    std::set<std::string> seen;
    for (ObId ob : w.rd.facts) {
        for (Part p = 0; p < g.num_parts(ob); ++p) {
            auto f = w.atom(g, ob, p, term);
            if (!f) {
                return fail(f.error());
            }
            if (!seen.insert(*f).second) {
                return fail(fmt::format("not expressible: the goal asks for two equal facts {} "
                                        "(PDDL facts are a set)",
                                        *f));
            }
            gt.statements.push_back(*f);
        }
    }
    for (std::size_t i = 0; i < gt.things.things.size(); ++i) {
        for (std::size_t j = i + 1; j < gt.things.things.size(); ++j) {
            const Thing &a = gt.things.things[i], &b = gt.things.things[j];
            if ((!a.pinned || !b.pinned) && w.may_coincide(a, b)) {
                gt.statements.push_back(fmt::format("(not (= {} {}))", gt.terms[i], gt.terms[j]));
            }
        }
    }
    return gt;
}

/// The action that reaches a pattern goal.
std::string goal_action_text(const Writer& w, const GoalText& g) {
    std::string params;
    for (const auto& [v, t] : g.params) {
        params += fmt::format("{}{} - {}", params.empty() ? "" : " ", v, t);
    }
    std::vector<std::string> pre = g.statements;
    pre.push_back(fmt::format("(not ({}))", w.goal_predicate));
    return fmt::format("  (:action {}\n    :parameters ({})\n    :precondition {}\n    :effect "
                       "({}))\n",
                       w.goal_action, params, conjunction(pre), w.goal_predicate);
}

/// Comment lines, one per note.
std::string comment_lines(const std::vector<std::string>& notes) {
    std::string out;
    for (const auto& n : notes) {
        out += "; " + n + "\n";
    }
    return out;
}

void add_notes(Writer& w) {
    for (const auto& [shape, pred] : w.marker_presence) {
        std::vector<std::string> facts;
        for (const auto& [key, mf] : w.marker_facts) {
            if (mf.shapes.count(shape) != 0) {
                facts.push_back("(" + mf.predicate + (mf.types.empty() ? ")" : " ...)"));
            }
        }
        w.notes.push_back(fmt::format(
            "The {} marker (a thing that rules create and delete whole; unnamed in a state) is no "
            "PDDL object: ({}) says that it exists, and a fact that refers to it leaves that "
            "argument out{}{}. Not expressed: a step that binds a rule's kept part to it, that "
            "deletes a part of an object in its place, or that would make a second {} marker.",
            shape, pred, facts.empty() ? "" : ": ", fmt::join(facts, ", "), shape));
    }
    if (w.creates_facts_not_sets) {
        w.notes.push_back("A rule that creates a fact requires it to be absent: a step that would "
                          "make a second equal fact part is not expressed.");
    }
    if (!w.goal_action.empty()) {
        w.notes.push_back(fmt::format(
            "The goal is a pattern (any things that fit, embedded monically): the action {} "
            "reaches ({}) when it holds, and every action requires (not ({})), so {} is the last "
            "step of a plan; it is left out when a plan is read back.",
            w.goal_action, w.goal_predicate, w.goal_predicate, w.goal_action));
    }
}

std::string goal_action_name(const plan::Domain& d) {
    NameSet actions;
    for (const auto& r : d.rules) {
        actions.take(detail::pddl_name(r->name.substr(0, r->name.find('~')), "a"));
    }
    return actions.take("reach-goal");
}

/// The problem's function values as `(= (road-length a d) 20)`, each argument the PDDL object of
/// the part it names; a value of a function no action's cost reads (not declared) is left out.
Result<std::vector<std::string>> value_facts(const Writer& w, const plan::Problem& p,
                                             const Things& init) {
    std::map<std::string, std::string> object; // part name -> PDDL object
    const acset::ACSet& x = *p.initial;
    for (const Thing& t : init.things) {
        for (std::uint32_t o = 0; o < t.part.size(); ++o) {
            if (t.part[o] != kNoPart && !t.marker) {
                object.emplace(x.part_name(ObId(o), t.part[o]), t.name);
            }
        }
    }
    std::vector<std::string> out;
    for (const auto& v : p.values) {
        std::string f = detail::pddl_name(v.function, "f");
        if (w.functions.count(f) == 0) {
            continue;
        }
        std::string args;
        for (const auto& a : v.args) {
            auto it = object.find(a);
            if (it == object.end()) {
                return fail(fmt::format("not expressible: the value of {} at {} names no PDDL "
                                        "object",
                                        v.function, a));
            }
            args += " " + it->second;
        }
        out.push_back(fmt::format("(= ({}{}) {})", f, args, v.value));
    }
    return out;
}

/// The problem file (w's goal action decided).
Result<std::string> problem_text(Writer& w, const GoalText& goal,
                                 const std::set<std::string>& constants) {
    const plan::Problem& p = *w.problem;
    NameSet names;
    auto init = detail::find_things(w.rd, *p.initial, w.marker_shapes, names, "the initial state");
    if (!init) {
        return fail(init.error());
    }
    auto facts = initial_facts(w, *init, *p.initial);
    if (!facts) {
        return fail(facts.error());
    }
    std::vector<std::string> objects;
    for (const Thing& t : init->things) {
        std::string decl = t.name + " - " + detail::thing_type(w.rd, t);
        if (!t.marker && constants.count(decl) == 0) {
            objects.push_back(decl);
        }
    }
    std::string out = fmt::format("; Exported by catplan from the problem {}.\n", p.name);
    out += fmt::format("(define (problem {})\n  (:domain {})\n", detail::pddl_name(p.name, "p"),
                       detail::pddl_name(p.domain->name, "d"));
    out += fmt::format("  (:objects {})\n", fmt::join(objects, " "));
    bool costs = plan::has_costs(*p.domain) && !p.counts_steps;
    if (plan::has_costs(*p.domain)) {
        auto values = value_facts(w, p, *init);
        if (!values) {
            return fail(values.error());
        }
        facts->insert(facts->end(), values->begin(), values->end());
        facts->emplace_back("(= (total-cost) 0)");
    }
    out += fmt::format("  (:init {})\n", fmt::join(*facts, "\n         "));
    std::string g = goal.pattern
                        ? fmt::format("({})", w.goal_predicate)
                        : (goal.statements.empty() ? "(and)" : conjunction(goal.statements));
    return out +
           fmt::format("  (:goal {}){}\n", g, costs ? "\n  (:metric minimize (total-cost)))" : ")");
}

/// A Writer with its reading and marker shapes.
Result<std::unique_ptr<Writer>> make_writer(const plan::Domain& domain,
                                            const plan::Problem* problem) {
    NameSet preds;
    auto rd = detail::read_schema(domain, problem, preds);
    if (!rd) {
        return fail(rd.error());
    }
    auto w = std::make_unique<Writer>(domain, problem, std::move(*rd), std::move(preds));
    if (auto ok = w->find_marker_shapes(); !ok) {
        return fail(ok.error());
    }
    return w;
}

} // namespace

Result<Exported> export_pddl(const plan::Domain& domain, const plan::Problem* problem) {
    if (problem != nullptr && !problem->goal_conditions.empty()) {
        return fail(fmt::format("not expressible by catplan's export: the goal's condition {} "
                                "(a negative goal), which the export does not write",
                                problem->goal_conditions.front().name));
    }
    auto made = make_writer(domain, problem);
    if (!made) {
        return fail(made.error());
    }
    Writer& w = **made;
    std::optional<GoalText> goal;
    if (problem != nullptr) {
        auto g = read_goal(w, *problem->goal);
        if (!g) {
            return fail(g.error());
        }
        goal = std::move(*g);
        if (goal->pattern) {
            w.goal_action = goal_action_name(domain);
            w.goal_predicate = w.preds.take("goal-reached");
        }
    }
    // A first pass names every fact about a marker, which the second needs for the dangling
    // condition.
    for (const auto& r : domain.rules) {
        if (auto a = w.read_rule(*r); !a) {
            return fail(a.error());
        }
    }
    Exported ex;
    std::set<std::string> constants;
    if (goal && goal->pattern) {
        constants = goal->pinned; // the goal action names them
    }
    std::string problem_file;
    if (problem != nullptr) {
        auto first = problem_text(w, *goal, constants); // names the initial marker facts
        if (!first) {
            return fail(first.error());
        }
    }
    auto actions = w.write_actions(ex.actions, constants);
    if (!actions) {
        return fail(actions.error());
    }
    if (problem != nullptr) {
        auto text = problem_text(w, *goal, constants);
        if (!text) {
            return fail(text.error());
        }
        problem_file = *text;
        if (goal->pattern) {
            *actions += goal_action_text(w, *goal);
            ex.goal_action = w.goal_action;
            ex.goal_params = goal->param_parts;
        }
        ex.source = std::make_shared<plan::Problem>(*problem);
    }
    w.notes.insert(w.notes.begin(), w.rd.notes.begin(), w.rd.notes.end());
    add_notes(w);
    std::string out = fmt::format("; Exported by catplan from the domain {}.\n", domain.name);
    out += comment_lines(w.notes);
    out += fmt::format("(define (domain {})\n", detail::pddl_name(domain.name, "d"));
    bool costs = plan::has_costs(domain);
    out += fmt::format("  (:requirements :strips :typing :negative-preconditions :equality{})\n",
                       costs ? " :action-costs" : "");
    out += fmt::format("  (:types{})\n", w.write_types());
    if (!constants.empty()) {
        out += fmt::format("  (:constants {})\n", fmt::join(constants, " "));
    }
    out += "  (:predicates\n" + w.write_predicates() + "  )\n";
    out += costs ? w.write_functions() : "";
    out += *actions + ")\n";
    ex.domain = std::move(out);
    if (!problem_file.empty()) {
        std::size_t eol = problem_file.find('\n') + 1;
        ex.problem =
            problem_file.substr(0, eol) + comment_lines(w.notes) + problem_file.substr(eol);
    }
    ex.notes = w.notes;
    ex.domain_ptr = std::make_shared<plan::Domain>(domain);
    return ex;
}

Result<std::string> export_domain(const plan::Domain& domain) {
    auto ex = export_pddl(domain, nullptr);
    if (!ex) {
        return fail(ex.error());
    }
    return ex->domain;
}

Result<std::string> export_problem(const plan::Problem& problem) {
    auto ex = export_pddl(*problem.domain, &problem);
    if (!ex) {
        return fail(ex.error());
    }
    return ex->problem;
}

} // namespace catplan::pddl
