#pragma once
// What export.cpp and export_problem.cpp share: the writer that turns rules, states and goals
// into PDDL text over one Reading (export_model.hpp), with the predicates it had to add (facts
// about markers, marker presence, the goal's).

#include "catplan/pddl/detail/export_model.hpp"
#include "catplan/pddl/export.hpp"

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace catplan::pddl::detail {

/// A term of an atom: a PDDL term, or a marker of some shape (left out of the atom).
struct TermText {
    std::string text;  // `?x` or `a`; empty for a marker
    std::string shape; // the marker's shape
};

/// A fact predicate with the marker arguments left out.
struct MarkerFact {
    std::string predicate;
    std::vector<std::string> types; // of the arguments kept
    std::set<std::string> shapes;   // of the markers it refers to
};

using TermFn = std::function<TermText(ObId, Part)>;

/// A rule's things and how they correspond: L things kept or deleted (markers), R things
/// created (markers) or the image of one L thing.
struct RuleThings {
    Things L, R;
    std::vector<std::size_t> r_to_l; // by R thing: its L thing, or kNone when created
};

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

/// One rule read as an action.
struct ActionText {
    std::string name;
    std::vector<std::pair<std::string, std::string>> params; // ?x, type
    std::vector<std::pair<ObId, Part>> param_parts;          // in L
    std::vector<std::size_t> param_things;                   // L things
    std::set<std::string> pos, neg, add, del;
    std::set<std::string> constants;       // "c - type"
    std::vector<std::string> inequalities; // "?x|?y"
    std::set<std::string> deleted_markers; // shapes
    std::vector<std::string> cost_terms;   // "(road-length ?from ?to)"
};

class Writer {
public:
    Writer(const plan::Domain& domain, const plan::Problem* problem, Reading rd, NameSet preds);

    const plan::Domain& domain;
    const plan::Problem* problem;
    Reading rd;
    NameSet preds;
    std::set<std::string> marker_shapes;
    std::map<std::string, std::string> marker_presence; // shape -> predicate
    std::map<std::string, MarkerFact> marker_facts;     // key -> predicate
    /// Facts with attribute values: `(IsClear_true ?x)`, by predicate: argument types.
    std::map<std::string, std::vector<std::string>> valued_facts;
    std::string goal_action, goal_predicate; // when the goal is a pattern
    std::vector<std::string> notes;
    bool creates_facts_not_sets = false;
    /// The functions the actions' costs read, by PDDL name: argument types.
    std::map<std::string, std::vector<std::string>> functions;
    /// The things of the problem's initial state, once a cost term names one.
    std::optional<Things> initial_things;

    /// `(on ?x ?y)` for fact part p of x (a marker argument left out: a MarkerFact); fails on an
    /// unset hom.
    Result<std::string> atom(const ACSet& x, ObId ob, Part p, const TermFn& term);
    /// Finds the marker shapes of the rules (things they create or delete whole).
    Result<bool> find_marker_shapes();
    /// One rule as an action (not yet merged with its variants).
    Result<ActionText> read_rule(const rewrite::Rule& rule);
    /// L's facts as preconditions, deleted, redirected and created facts as effects.
    Result<bool> rule_facts(const rewrite::Rule& rule, const TermFn& l_term, const TermFn& r_term,
                            ActionText& a);
    /// What the things of L and R ask and change: membership, attribute values, markers.
    Result<bool> rule_things_conditions(const rewrite::Rule& rule, const RuleThings& rt,
                                        const std::vector<std::string>& term, ActionText& a);
    /// The rule's cost terms as PDDL function terms on its parameters (recorded in functions).
    Result<bool> rule_cost_terms(const rewrite::Rule& rule, const Things& L,
                                 const std::vector<std::string>& term, ActionText& a);
    /// A part a cost term names (no parameter: a PDDL constant) as (name, type): pinned in L,
    /// else an object of the problem's initial state, whose type only the problem gives.
    Result<std::pair<std::string, std::string>> named_cost_argument(const rewrite::Rule& rule,
                                                                    const Things& L,
                                                                    const std::string& function,
                                                                    const std::string& name);
    /// The `(:functions ...)` declaration: total-cost and the functions the costs read.
    std::string write_functions() const;
    /// Negative application conditions as negative preconditions.
    Result<bool> rule_nacs(const rewrite::Rule& rule, const TermFn& l_term, ActionText& a);
    /// The negative preconditions that keep a deleted marker from dangling: no fact the action
    /// leaves may refer to it.
    Result<bool> marker_dangling(const std::string& rule, ActionText& a);
    /// The actions, merged by variant group, as text; `actions` gets one entry per action.
    Result<std::string> write_actions(std::vector<Exported::Action>& actions,
                                      std::set<std::string>& constants);
    /// The `(:predicates ...)` body.
    std::string write_predicates() const;
    /// The ` T - parent ...` of `(:types ...)`.
    std::string write_types() const;
    /// The presence predicate of a marker shape (made on first use).
    const std::string& presence(const std::string& shape);
    /// Attribute facts of a thing of x: Bool values (value, fact) and value predicates.
    void attr_facts(const ACSet& x, const Thing& t, const std::string& term,
                    std::vector<std::pair<std::string, bool>>& out) const;
    /// Whether two things of one state may be one PDDL object (then a monic match needs them
    /// distinct): they share an object and, in a forest, one type is below the other.
    bool may_coincide(const Thing& a, const Thing& b) const;
};

} // namespace catplan::pddl::detail
