// The sections of PDDL domains and problems (pddl.hpp); s-expressions, typed lists and formulas are
// read by detail/reader.hpp.

#include "catplan/pddl/detail/reader.hpp"
#include "catplan/pddl/pddl.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <unordered_set>

namespace catplan::pddl {

namespace {

using detail::FormulaReader;
using detail::is_name;
using detail::Parser;
using detail::Scope;
using detail::SExpr;
using detail::TypeScope;

// ---- domains ----------------------------------------------------------------------------------

const std::unordered_set<std::string> kSupported = {":strips", ":typing", ":negative-preconditions",
                                                    ":equality", ":action-costs"};

// PDDL's other requirements (PDDL 3.1): valid, and named in a warning. A requirement only allows
// constructs; each construct catplan does not read is refused where it is used, so a domain that
// declares :adl and uses only what catplan reads (as many do) is read, as other planners read it.
const std::unordered_set<std::string> kUnsupported = {":disjunctive-preconditions",
                                                      ":existential-preconditions",
                                                      ":universal-preconditions",
                                                      ":quantified-preconditions",
                                                      ":conditional-effects",
                                                      ":fluents",
                                                      ":numeric-fluents",
                                                      ":object-fluents",
                                                      ":adl",
                                                      ":durative-actions",
                                                      ":duration-inequalities",
                                                      ":continuous-effects",
                                                      ":derived-predicates",
                                                      ":timed-initial-literals",
                                                      ":preferences",
                                                      ":constraints",
                                                      ":goal-utilities",
                                                      ":time"};

void read_requirements(Parser& p, const SExpr& e, Domain& d) {
    for (std::size_t i = 1; i < e.items.size(); ++i) {
        const SExpr& r = e.items[i];
        if (r.list || r.atom.empty() || r.atom[0] != ':') {
            p.error(r.range, "expected a requirement such as ':typing'");
            continue;
        }
        if (kUnsupported.count(r.atom) != 0) {
            p.warning(r.range, fmt::format("requirement '{}' is read only as far as catplan "
                                           "goes (:strips, :typing, :negative-preconditions, "
                                           ":equality, :action-costs); any other construct it "
                                           "allows is refused where it is used",
                                           r.atom));
            continue;
        }
        if (kSupported.count(r.atom) == 0) {
            p.error(r.range, fmt::format("unknown requirement '{}'", r.atom));
            continue;
        }
        d.requirements.push_back(r.atom);
    }
}

// A type listed again gets one more parent; a type named only as a parent is declared below
// object, as most planners do.
void read_types(Parser& p, const SExpr& e, Domain& d) {
    auto list = p.typed_list(e.items, 1, false, TypeScope{}, "(:types ...)");
    auto declare = [&](const std::string& name, SourceRange at) -> Type& {
        for (auto& t : d.types) {
            if (t.name == name) {
                return t;
            }
        }
        d.types.push_back({name, {}, at});
        return d.types.back();
    };
    for (const auto& t : list) {
        if (t.name != "object") {
            declare(t.name, t.range).parents.push_back(t.type);
        }
    }
    for (const auto& t : list) {
        if (d.find_type(t.type) == nullptr) {
            declare(t.type, t.range).parents.emplace_back("object");
        }
    }
    detail::order_types(p, d);
}

void read_predicates(Parser& p, const SExpr& e, Domain& d) {
    for (std::size_t i = 1; i < e.items.size(); ++i) {
        const SExpr& pe = e.items[i];
        if (!pe.list || pe.items.empty() || !is_name(pe.items[0])) {
            p.error(pe.range, "expected a predicate '(name ?x - type ...)'");
            continue;
        }
        if (d.find_predicate(pe.items[0].atom) != nullptr) {
            p.error(pe.range,
                    fmt::format("the predicate '{}' is declared twice", pe.items[0].atom));
            continue;
        }
        auto params = p.typed_list(pe.items, 1, true, TypeScope{&d, &d}, "a predicate");
        d.predicates.push_back({pe.items[0].atom, std::move(params), pe.range});
        p.report_duplicates(d.predicates.back().params, "parameter");
    }
}

// `(:functions (total-cost) - number (road-length ?a ?b - place) - number)`; an untyped function
// is a number too (PDDL 3.1).
void read_functions(Parser& p, const SExpr& e, Domain& d) {
    for (std::size_t i = 1; i < e.items.size(); ++i) {
        const SExpr& fe = e.items[i];
        if (fe.is_atom("-")) {
            if (i + 1 >= e.items.size()) {
                p.error(fe.range, "expected a type after '-' in (:functions ...)");
            } else if (!e.items[i + 1].is_atom("number")) {
                p.unsupported(e.items[i + 1].range,
                              "unsupported function type (object fluents, :object-fluents): "
                              "catplan's functions are numbers");
            }
            ++i;
            continue;
        }
        if (!fe.list || fe.items.empty() || !is_name(fe.items[0])) {
            p.error(fe.range, "expected a function '(name ?x - type ...)'");
            continue;
        }
        if (d.find_function(fe.items[0].atom) != nullptr) {
            p.error(fe.range, fmt::format("the function '{}' is declared twice", fe.items[0].atom));
            continue;
        }
        auto params = p.typed_list(fe.items, 1, true, TypeScope{&d, &d}, "a function");
        d.functions.push_back({fe.items[0].atom, std::move(params), fe.range});
        p.report_duplicates(d.functions.back().params, "parameter");
    }
}

void read_action(Parser& p, const SExpr& e, Domain& d) {
    if (e.items.size() < 2 || !is_name(e.items[1])) {
        p.error(e.range, "expected an action name after ':action'");
        return;
    }
    Action a;
    a.name = e.items[1].atom;
    a.range = e.items[1].range;
    bool has_effect = false;
    std::vector<std::string_view> fields; // given so far: a second one would replace the first
    for (std::size_t i = 2; i + 1 < e.items.size() + 1; i += 2) {
        const SExpr& key = e.items[i];
        if (i + 1 >= e.items.size()) {
            p.error(key.range, "expected a value after this keyword");
            return;
        }
        if (key.is_atom(":parameters") || key.is_atom(":precondition") || key.is_atom(":effect")) {
            if (std::find(fields.begin(), fields.end(), key.atom) != fields.end()) {
                p.error(key.range,
                        fmt::format("'{}' is given twice in the action '{}'", key.atom, a.name));
                return;
            }
            fields.push_back(key.atom);
        }
        const SExpr& value = e.items[i + 1];
        Scope scope{d, &a.params};
        FormulaReader fr(p, scope);
        if (key.is_atom(":parameters")) {
            if (!value.list) {
                p.error(value.range, "expected a parameter list '(?x - type ...)'");
                return;
            }
            a.params = p.typed_list(value.items, 0, true, TypeScope{&d, &d}, "the parameters");
            p.report_duplicates(a.params, "parameter");
        } else if (key.is_atom(":precondition")) {
            auto pre = fr.conjunction(value, true, true);
            if (pre) {
                a.precondition = *pre;
            }
        } else if (key.is_atom(":effect")) {
            has_effect = true;
            fr.effect(value, a);
        } else {
            p.error(key.range, fmt::format("unsupported action field '{}'", key.atom));
        }
    }
    if (!has_effect) {
        p.error(e.range, fmt::format("the action '{}' has no ':effect'", a.name));
    }
    if (d.find_action(a.name) != nullptr) {
        p.error(a.range, fmt::format("the action '{}' is declared twice", a.name));
        return;
    }
    d.actions.push_back(std::move(a));
}

void read_domain_section(Parser& p, const SExpr& e, Domain& d) {
    std::string_view h = e.head();
    if (h == ":requirements") {
        read_requirements(p, e, d);
    } else if (h == ":types") {
        read_types(p, e, d);
    } else if (h == ":constants") {
        auto more = p.typed_list(e.items, 1, false, TypeScope{&d, &d}, "(:constants ...)");
        p.report_duplicates(more, "constant", d.constants);
        d.constants.insert(d.constants.end(), more.begin(), more.end());
    } else if (h == ":predicates") {
        read_predicates(p, e, d);
    } else if (h == ":functions") {
        read_functions(p, e, d);
    } else if (h == ":action") {
        read_action(p, e, d);
    } else if (h == ":durative-action" || h == ":derived" || h == ":constraints") {
        p.unsupported(e.items[0].range, fmt::format("unsupported domain section '{}' ({})", h,
                                                    h == ":derived"       ? ":derived-predicates"
                                                    : h == ":constraints" ? ":constraints"
                                                                          : ":durative-actions"));
    } else {
        p.error(e.range, h.empty() ? std::string("expected a domain section '(:keyword ...)'")
                                   : fmt::format("unknown domain section '{}'", h));
    }
}

/// `(define (KIND name) sections...)`: the name, or nullopt after an error.
std::optional<std::string> read_define(Parser& p, const SExpr& top, std::string_view kind) {
    if (!p.expect_head(top, "define", "at the top of the file")) {
        return std::nullopt;
    }
    if (top.items.size() < 2 || top.items[1].head() != kind || top.items[1].items.size() != 2 ||
        !is_name(top.items[1].items[1])) {
        p.error(top.items.size() < 2 ? top.range : top.items[1].range,
                fmt::format("expected '({} NAME)' after 'define'", kind));
        return std::nullopt;
    }
    return top.items[1].items[1].atom;
}

// ---- problems -----------------------------------------------------------------------------------

void read_init(Parser& p, FormulaReader& fr, const SExpr& e, Problem& pr) {
    for (std::size_t k = 1; k < e.items.size(); ++k) {
        const SExpr& f = e.items[k];
        if (f.head() == "=") {
            fr.init_value(f, pr);
        } else if (f.head() == "at" && f.items.size() == 3 && !f.items[1].list &&
                   !f.items[1].atom.empty() &&
                   (std::isdigit(static_cast<unsigned char>(f.items[1].atom[0])) != 0)) {
            p.unsupported(f.items[0].range, "unsupported timed initial literal '(at TIME ...)' "
                                            "(:timed-initial-literals)");
        } else if (auto a = fr.atom(f, false)) {
            pr.init.push_back(*a);
        }
    }
}

void read_metric(Parser& p, const Domain& domain, const SExpr& e, Problem& pr) {
    bool total_cost = e.items.size() == 3 && e.items[1].is_atom("minimize") && e.items[2].list &&
                      e.items[2].items.size() == 1 && e.items[2].items[0].is_atom("total-cost");
    if (!total_cost) {
        p.unsupported(e.range, "unsupported metric (catplan minimizes '(total-cost)' only)");
        return;
    }
    if (domain.find_function("total-cost") == nullptr) {
        p.error(e.items[2].range, "unknown function 'total-cost' (the domain does not declare it)");
        return;
    }
    pr.metric = true;
}

// One section of a problem into pr; false when the problem names another domain (read against
// this one, every later name would be an error of its own).
bool read_problem_section(Parser& p, FormulaReader& fr, const Domain& domain, const SExpr& e,
                          Problem& pr) {
    std::string_view h = e.head();
    if (h == ":domain" && e.items.size() == 2 && is_name(e.items[1])) {
        pr.domain_name = e.items[1].atom;
        if (pr.domain_name != domain.name) {
            p.error(e.items[1].range, fmt::format("the problem is for domain '{}', not '{}'",
                                                  pr.domain_name, domain.name));
            return false;
        }
    } else if (h == ":requirements") {
        Domain scratch;
        read_requirements(p, e, scratch);
    } else if (h == ":objects") {
        auto more = p.typed_list(e.items, 1, false, TypeScope{&domain, nullptr}, "(:objects ...)");
        auto earlier = domain.constants;
        earlier.insert(earlier.end(), pr.objects.begin(), pr.objects.end());
        p.report_duplicates(more, "object", earlier);
        pr.objects.insert(pr.objects.end(), more.begin(), more.end());
    } else if (h == ":init") {
        read_init(p, fr, e, pr);
    } else if (h == ":goal" && e.items.size() == 2) {
        if (auto g = fr.conjunction(e.items[1], false, true)) {
            pr.goal = *g;
        }
    } else if (h == ":metric") {
        read_metric(p, domain, e, pr);
    } else if (h == ":constraints" || h == ":length") {
        p.unsupported(e.items[0].range, fmt::format("unsupported problem section '{}'", h));
    } else {
        p.error(e.range, h.empty() ? std::string("expected a problem section '(:keyword ...)'")
                                   : fmt::format("unknown problem section '{}'", h));
    }
    return true;
}

} // namespace

// ---- public -------------------------------------------------------------------------------------

std::string Atom::to_string() const {
    std::string s = "(" + predicate;
    for (const auto& t : args) {
        s += " " + std::string(t.variable ? "?" : "") + t.name;
    }
    return s + ")";
}

std::string Literal::to_string() const {
    return positive ? atom.to_string() : "(not " + atom.to_string() + ")";
}

std::string CostTerm::to_string() const {
    return fluent ? fluent->to_string() : std::to_string(number);
}

const Type* Domain::find_type(std::string_view type_name) const {
    for (const auto& t : types) {
        if (t.name == type_name) {
            return &t;
        }
    }
    return nullptr;
}

const Predicate* Domain::find_predicate(std::string_view predicate_name) const {
    for (const auto& p : predicates) {
        if (p.name == predicate_name) {
            return &p;
        }
    }
    return nullptr;
}

const Function* Domain::find_function(std::string_view function_name) const {
    for (const auto& f : functions) {
        if (f.name == function_name) {
            return &f;
        }
    }
    return nullptr;
}

const Action* Domain::find_action(std::string_view action_name) const {
    for (const auto& a : actions) {
        if (a.name == action_name) {
            return &a;
        }
    }
    return nullptr;
}

bool Domain::is_subtype(std::string_view sub, std::string_view super) const {
    // Most types have one parent: their chain is walked without allocating (this runs for every
    // argument of every step a plan names).
    std::string_view up = sub;
    for (std::size_t depth = 0; depth <= types.size(); ++depth) {
        if (up == super) {
            return true;
        }
        const Type* info = find_type(up);
        if (info == nullptr || info->parents.empty()) {
            return false;
        }
        if (info->parents.size() > 1) {
            break;
        }
        up = info->parents[0];
    }
    // Depth first along the parents, each type once (the graph is acyclic, but may have many
    // paths between two types).
    std::vector<std::string_view> stack{sub};
    std::unordered_set<std::string_view> seen{sub};
    while (!stack.empty()) {
        std::string_view t = stack.back();
        stack.pop_back();
        if (t == super) {
            return true;
        }
        const Type* info = find_type(t);
        if (info == nullptr) {
            continue;
        }
        for (const auto& q : info->parents) {
            if (seen.insert(q).second) {
                stack.emplace_back(q);
            }
        }
    }
    return false;
}

bool Domain::may_share(std::string_view a, std::string_view b) const {
    return is_subtype(a, b) || is_subtype(b, a) ||
           std::any_of(types.begin(), types.end(), [&](const Type& t) {
               return is_subtype(t.name, a) && is_subtype(t.name, b);
           });
}

bool Domain::has_costs() const {
    return std::any_of(actions.begin(), actions.end(),
                       [](const Action& a) { return !a.cost.empty(); });
}

std::optional<std::int64_t> Problem::value_of(const Atom& term) const {
    for (const auto& v : values) {
        if (v.term.predicate == term.predicate && v.term.args == term.args) {
            return v.value;
        }
    }
    return std::nullopt;
}

std::optional<Domain> parse_domain(std::uint32_t file, const SourceManager& sources,
                                   DiagnosticSink& sink) {
    auto top = detail::read_top(file, sources, sink);
    if (!top) {
        return std::nullopt;
    }
    Parser p(sink);
    auto name = read_define(p, *top, "domain");
    if (!name) {
        return std::nullopt;
    }
    Domain d;
    d.name = *name;
    d.range = top->items[1].range;
    d.types.push_back({"object", {}, {}});
    for (std::size_t i = 2; i < top->items.size(); ++i) {
        read_domain_section(p, top->items[i], d);
    }
    if (p.failed()) {
        return std::nullopt;
    }
    return d;
}

std::optional<Problem> parse_problem(std::uint32_t file, const Domain& domain,
                                     const SourceManager& sources, DiagnosticSink& sink) {
    auto top = detail::read_top(file, sources, sink);
    if (!top) {
        return std::nullopt;
    }
    Parser p(sink);
    auto name = read_define(p, *top, "problem");
    if (!name) {
        return std::nullopt;
    }
    Problem pr;
    pr.name = *name;
    pr.range = top->items[1].range;
    ObjectIndex objects(domain, pr);
    Scope scope{domain, nullptr, &pr, &objects};
    FormulaReader fr(p, scope);
    for (std::size_t i = 2; i < top->items.size(); ++i) {
        if (!read_problem_section(p, fr, domain, top->items[i], pr)) {
            return std::nullopt;
        }
    }
    if (p.failed()) {
        return std::nullopt;
    }
    return pr;
}

const TypedName* ObjectIndex::find(std::string_view name) const {
    if (d_->constants.data() != constants_ || p_->objects.data() != objects_ ||
        d_->constants.size() != num_constants_ || p_->objects.size() != num_objects_) {
        // The names are views into the lists: a list that moved or grew is indexed again.
        index_.clear();
        for (const auto* list : {&d_->constants, &p_->objects}) {
            for (const auto& o : *list) {
                index_.emplace(o.name, &o); // the first of a name stays
            }
        }
        constants_ = d_->constants.data();
        objects_ = p_->objects.data();
        num_constants_ = d_->constants.size();
        num_objects_ = p_->objects.size();
    }
    auto it = index_.find(name);
    return it == index_.end() ? nullptr : it->second;
}

} // namespace catplan::pddl
