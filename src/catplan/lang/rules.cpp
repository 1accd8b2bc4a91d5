// Rules (docs/language.md, "Rules"): the blocks Pre, Keep, Eff and the application conditions
// NAC and PAC (or the slides' L, K, R, l, r) are partial presentations; L, K and R are their
// states, l : K -> L and r : K -> R the unique morphisms their generators' names determine.

#include "catplan/colimit/colimit.hpp"
#include "catplan/hom/hom_search.hpp"
#include "catplan/lang/detail/colimit.hpp"
#include "catplan/lang/detail/elaboration.hpp"
#include "catplan/lang/detail/elaborator.hpp"
#include "catplan/lang/detail/rule_elaboration.hpp"
#include "catplan/rewrite/rule.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace catplan::lang::detail {
namespace {

using acset::ACSet;
using acset::Value;
using schema::Schema;
using schema::ValueKind;

// `cost = 3 + road_length(from, to)`: what a step of the rule costs (PDDL's action costs); its
// terms are checked against the parameters once they are known.
void rule_cost(const Expr& st, RuleSource& src, DiagnosticSink& sink) {
    if (src.cost != nullptr) {
        auto& d = sink.error(st.range, "the cost is given twice");
        d.notes.emplace_back(src.cost->range, "first given here");
    } else {
        src.cost = &st;
    }
}

// The summands of `a + b + c`.
void summands(const Expr& e, std::vector<const Expr*>& out) {
    if (e.is_binary("+")) {
        summands(e.args[0], out);
        summands(e.args[1], out);
    } else {
        out.push_back(&e);
    }
}

// `action = stack(x, x)`: the action a step of the rule is a step of (rewrite::ActionOf); its
// arguments are checked against the parameters once they are known.
void rule_action(const Expr& st, RuleSource& src, DiagnosticSink& sink) {
    const Expr& v = st.args[1];
    if (src.action != nullptr) {
        auto& d = sink.error(st.range, "the action is given twice");
        d.notes.emplace_back(src.action->range, "first given here");
    } else if (v.kind != Expr::Kind::Call && v.kind != Expr::Kind::Name) {
        sink.error(v.range, fmt::format("expected the action as 'name(argument, ...)', found '{}'",
                                        to_string(v)));
    } else {
        src.action = &st;
    }
}

// The statements of `Pre => @join begin ... end` / `Pre => begin ... end` into src.blocks, and
// the rule's `cost = N` and `action = a(x, y)`.
void rule_blocks(const std::vector<Expr>& body, RuleSource& src, DiagnosticSink& sink) {
    static const std::vector<std::string> ours = {"Pre", "Keep", "Eff", "NAC", "PAC"};
    static const std::vector<std::string> span = {"L", "K", "R", "l", "r"};
    const auto& allowed = src.span_form ? span : ours;
    std::map<std::string, SourceRange> seen;
    for (const auto& st : body) {
        if (st.is_binary("=") && st.args[0].kind == Expr::Kind::Name && st.args[0].text == "cost") {
            rule_cost(st, src, sink);
            continue;
        }
        if (st.is_binary("=") && st.args[0].kind == Expr::Kind::Name &&
            st.args[0].text == "action") {
            rule_action(st, src, sink);
            continue;
        }
        const std::vector<Expr>* stmts = nullptr;
        if (st.is_binary("=>") && st.args[0].kind == Expr::Kind::Name) {
            stmts = block_body(st.args[1]);
        }
        if (stmts == nullptr) {
            sink.error(st.range, fmt::format("expected a block of the rule, '{} => @join begin ... "
                                             "end' or '{} => begin ... end', found '{}'",
                                             allowed[0], allowed[0], to_string(st)));
            continue;
        }
        const Expr& name = st.args[0];
        if (std::find(allowed.begin(), allowed.end(), name.text) == allowed.end()) {
            std::string list;
            for (std::size_t i = 0; i < allowed.size(); ++i) {
                list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + allowed[i];
            }
            sink.error(name.range, fmt::format("unknown block '{}' in rule '{}' (expected "
                                               "{})",
                                               name.text, src.name, list));
            continue;
        }
        if (name.text != "NAC" && name.text != "PAC") {
            auto [it, fresh] = seen.emplace(name.text, name.range);
            if (!fresh) {
                auto& d =
                    sink.error(name.range, fmt::format("block '{}' is given twice", name.text));
                d.notes.emplace_back(it->second, "first given here");
                continue;
            }
        }
        src.blocks.push_back({name.text, st.range, stmts});
    }
}

} // namespace

const std::vector<Expr>* block_body(const Expr& e) {
    if (e.kind == Expr::Kind::Block) {
        return &e.args;
    }
    if (e.kind == Expr::Kind::Macro && e.macro->name == "join" && e.macro->has_body &&
        e.macro->header.empty()) {
        return &e.macro->body;
    }
    return nullptr;
}

bool rule_source(Elaborator& ctx, const MacroCall& form, const std::string& assigned,
                 SourceRange assigned_range, const std::shared_ptr<Schema>& default_schema,
                 RuleSource& src) {
    DiagnosticSink& sink = ctx.sink;
    src.range = form.range;
    const Expr* schema_name = nullptr;
    bool ok = form.has_body;
    if (form.name == "rule") {
        // @rule name(params...) [on Schema] begin ... end
        const auto& h = form.header;
        if (!h.empty() && (h[0].kind == Expr::Kind::Name || h[0].kind == Expr::Kind::Call)) {
            src.name = h[0].text;
            src.name_range = h[0].kind == Expr::Kind::Call ? h[0].name_range : h[0].range;
            if (h[0].kind == Expr::Kind::Call) {
                src.has_params = true;
                for (const auto& a : h[0].args) {
                    src.params.push_back(&a);
                }
            }
        } else {
            ok = false;
        }
        if (h.size() == 3 && h[1].kind == Expr::Kind::Name && h[1].text == "on" &&
            h[2].kind == Expr::Kind::Name) {
            schema_name = &h[2];
        } else if (h.size() != 1 || !default_schema) {
            ok = false;
        }
        if (!ok) {
            sink.error(form.range, "expected '@rule name(parameters...) on Schema begin "
                                   "... end' (inside a domain, 'on Schema' may be left "
                                   "out)");
            return false;
        }
    } else {
        // name = @migration SchRule Schema begin L => ... end (the authors' slides), or
        // :name => @migration(Schema, begin Pre => ... end) (the paper's listing).
        src.name = assigned;
        src.name_range = assigned_range;
        const auto& h = form.header;
        if (h.size() == 2 && h[0].kind == Expr::Kind::Name && h[0].text == "SchRule" &&
            h[1].kind == Expr::Kind::Name) {
            src.span_form = true;
            schema_name = &h[1];
        } else if (h.size() == 1 && h[0].kind == Expr::Kind::Name) {
            schema_name = &h[0];
        } else {
            ok = false;
        }
        if (!ok || assigned.empty()) {
            sink.error(form.range, "expected 'name = @migration SchRule Schema begin L => "
                                   "... end' or ':name => @migration(Schema, begin Pre "
                                   "=> ... end)' in a domain");
            return false;
        }
    }
    if (schema_name != nullptr) {
        src.schema = ctx.lookup_schema(*schema_name, true);
    } else {
        src.schema = default_schema;
    }
    if (!src.schema) {
        return false;
    }
    rule_blocks(form.body, src, sink);
    return true;
}

namespace {

// Why no morphism from -> to extends the bindings of opt: when the names fix every part, the
// first failure of the map they give; otherwise a general reason.
std::string why_no_morphism(const ACSet& from, const ACSet& to, const hom::HomSearchOptions& opt) {
    hom::ACSetMorphism m;
    const Schema& s = from.schema();
    m.components.resize(s.num_obs());
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        m.components[o].assign(from.num_parts(ObId(o)), kNoPart);
    }
    m.var_components.resize(s.num_attr_types());
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        m.var_components[t].assign(from.num_vars(AttrTypeId(t)), Value());
    }
    for (const auto& b : opt.initial) {
        m.components[b.ob.index()][b.dom] = b.codom;
    }
    for (const auto& b : opt.initial_vars) {
        m.var_components[b.type.index()][b.var] = b.value;
    }
    bool complete = true;
    for (const auto& c : m.components) {
        for (Part p : c) {
            complete = complete && p != kNoPart;
        }
    }
    if (complete) {
        for (const auto& f : hom::naturality_failures(m, from, to)) {
            if (f.kind != hom::NaturalityFailureKind::VarImageInvalid) {
                return hom::describe(f, from, to);
            }
        }
    }
    return "it says something about its parts that the other block does not";
}

// The elaboration of one rule, step by step: L (with the cells Eff's expressions read), R, K,
// the legs, the application conditions, the parameters and the expressions.
class RuleElaboration {
public:
    RuleElaboration(Elaborator& ctx, const RuleSource& src)
        : ctx_(ctx),
          src_(src),
          schema_(src.schema),
          sink_(&ctx.sink),
          errors_(ctx.sink.num_errors()),
          lc_(schema_, ctx.inferred_kinds(*schema_)),
          rc_(schema_, ctx.inferred_kinds(*schema_)),
          kc_(schema_, ctx.inferred_kinds(*schema_)) {
        pre_name_ = src.span_form ? "L" : "Pre";
        keep_name_ = src.span_form ? "K" : "Keep";
        eff_name_ = src.span_form ? "R" : "Eff";
    }

    rewrite::RulePtr run() {
        sort_blocks();
        elaborate_pre();
        elaborate_eff();
        if (failed()) {
            return nullptr;
        }
        ACSet L = lc_.build_partial();
        for (auto& [st, e] : translated_) {
            fix_inputs(lc_, e);
            // After fix_inputs: a cell Pre fixes is a constant too.
            check_constants(e, value_side(*st).range, *sink_);
        }
        ACSet R = rc_.build_partial();
        elaborate_keep();
        if (failed()) {
            return nullptr;
        }
        auto rule = std::make_shared<rewrite::Rule>(schema_);
        rule->name = src_.name;
        rule->range = src_.name_range;
        rule->L = std::move(L);
        rule->K = kc_.build_partial();
        rule->R = std::move(R);
        if (!legs(*rule)) {
            return nullptr;
        }
        for (const RuleBlock* b : conds_) {
            if (!condition(*rule, *b)) {
                return nullptr;
            }
        }
        parameters(*rule);
        if (src_.cost != nullptr) {
            cost(*rule, src_.cost->args[1]);
        }
        if (src_.action != nullptr) {
            action(*rule, src_.action->args[1]);
        }
        effect_exprs(*rule);
        if (failed()) {
            return nullptr;
        }
        check(*rule);
        if (failed()) {
            return nullptr;
        }
        return rule;
    }

private:
    bool failed() const { return ctx_.sink.num_errors() != errors_; }

    // An argument of an action or a cost term: a parameter of the rule or a part name in
    // quotes. nullopt after an error.
    std::optional<rewrite::ActionOf::Argument> argument(const rewrite::Rule& rule,
                                                        const Expr& arg) {
        if (arg.kind == Expr::Kind::String) {
            return rewrite::ActionOf::Argument{-1, arg.text};
        }
        auto p = std::find_if(rule.parameters.begin(), rule.parameters.end(),
                              [&](const auto& q) { return q.name == arg.text; });
        if (arg.kind != Expr::Kind::Name || p == rule.parameters.end()) {
            ctx_.sink.error(arg.range, fmt::format("expected a parameter of rule '{}' or a part "
                                                   "name in quotes, found '{}'",
                                                   rule.name, to_string(arg)));
            return std::nullopt;
        }
        return rewrite::ActionOf::Argument{static_cast<int>(p - rule.parameters.begin()), {}};
    }

    // `cost = 2 + road_length(from, to)`: non-negative integers and functions of the
    // parameters, whose values a problem gives (plan/costs.hpp), summed.
    void cost(rewrite::Rule& rule, const Expr& e) {
        rewrite::Cost c;
        std::vector<const Expr*> terms;
        summands(e, terms);
        for (const Expr* t : terms) {
            if (t->kind == Expr::Kind::Int && t->int_value >= 0) {
                if (__builtin_add_overflow(c.constant, t->int_value, &c.constant)) {
                    ctx_.sink.error(t->range, "the cost is out of range");
                }
                continue;
            }
            if (t->kind != Expr::Kind::Call) {
                ctx_.sink.error(t->range, fmt::format("expected the cost as a non-negative "
                                                      "integer, a function of the parameters "
                                                      "such as 'length(from, to)', or a sum of "
                                                      "them, found '{}'",
                                                      to_string(*t)));
                continue;
            }
            rewrite::Cost::Term term{t->text, {}};
            for (const auto& arg : t->args) {
                if (auto x = argument(rule, arg)) {
                    term.arguments.push_back(std::move(*x));
                }
            }
            c.terms.push_back(std::move(term));
        }
        rule.cost = std::move(c);
    }

    // The arguments of `action = a(x, "c")`: parameters of the rule (one may be given twice:
    // the rule identifies those arguments) or part names in quotes; every parameter is given.
    void action(rewrite::Rule& rule, const Expr& e) {
        rewrite::ActionOf a{e.text, {}};
        std::vector<bool> given(rule.parameters.size(), false);
        for (const auto& arg : e.args) {
            if (auto x = argument(rule, arg)) {
                if (x->parameter >= 0) {
                    given[static_cast<std::size_t>(x->parameter)] = true;
                }
                a.arguments.push_back(std::move(*x));
            }
        }
        for (std::size_t i = 0; i < given.size(); ++i) {
            if (!given[i]) {
                ctx_.sink.error(e.range, fmt::format("the action does not give the parameter "
                                                     "'{}' of rule '{}'",
                                                     rule.parameters[i].name, rule.name));
            }
        }
        rule.action = std::move(a);
    }

    void sort_blocks() {
        for (const auto& b : src_.blocks) {
            if (b.name == "Pre" || b.name == "L") {
                pre_ = &b;
            } else if (b.name == "Keep" || b.name == "K") {
                keep_ = &b;
            } else if (b.name == "Eff" || b.name == "R") {
                eff_ = &b;
            } else if (b.name == "l") {
                lmap_ = &b;
            } else if (b.name == "r") {
                rmap_ = &b;
            } else {
                conds_.push_back(&b);
            }
        }
    }

    // The computed side of an expression statement is the operator expression; the other side
    // names the cell.
    static const Expr& value_side(const Expr& st) {
        return is_operator_expr(st.args[1]) ? st.args[1] : st.args[0];
    }

    static const Expr& cell_side(const Expr& st) {
        return is_operator_expr(st.args[1]) ? st.args[0] : st.args[1];
    }

    // L: the precondition, plus a variable for every cell an expression of Eff reads.
    void elaborate_pre() {
        declare_all(lc_, pre_, true);
        equations_all(lc_, pre_, true, nullptr);
        std::vector<const Expr*> expr_stmts;
        {
            // Collect Eff's expression statements first (R's elaboration reports the rest).
            Colimit scratch(schema_, ctx_.inferred_kinds(*schema_));
            with_sink(false, [&] { equations_all(scratch, eff_, false, &expr_stmts); });
        }
        for (const Expr* st : expr_stmts) {
            ValueKind k = ValueKind::Unknown;
            auto e = translate(lc_, value_side(*st), k, *sink_);
            if (e) {
                e->range = st->range;
                translated_.emplace_back(st, std::move(*e));
                kinds_.push_back(k);
            }
        }
    }

    // R: Keep's statements hold in Eff too, so Eff need only say what changes.
    void elaborate_eff() {
        rc_.allow_redeclare();
        if (!src_.span_form) {
            declare_all(rc_, keep_, false);
        }
        declare_all(rc_, eff_, true);
        if (!src_.span_form) {
            equations_all(rc_, keep_, false, nullptr);
        }
        std::vector<const Expr*> unused;
        equations_all(rc_, eff_, true, &unused);
        for (std::size_t i = 0; i < translated_.size(); ++i) {
            const Expr* st = translated_[i].first;
            const Expr& cell = cell_side(*st);
            auto t = rc_.eval(cell, *sink_);
            if (!t) {
                continue;
            }
            if (t->kind != Term::Kind::Value || cell.kind != Expr::Kind::Call) {
                sink_->error(cell.range, fmt::format("the left side of a computed attribute must "
                                                     "be an attribute of a part, found '{}'",
                                                     to_string(cell)));
                continue;
            }
            ValueKind want = schema_->attr_type(rc_.value_type(t->node)).kind;
            ValueKind got = kinds_[i];
            if (want != got) {
                bool quotient = want == ValueKind::Int && got == ValueKind::Float &&
                                has_division(value_side(*st));
                sink_->error(st->range,
                             fmt::format("type error: the expression gives {} but '{}' "
                                         "holds {} values{}",
                                         kind_phrase(got), to_string(cell), schema::to_string(want),
                                         quotient ? " ('/' gives a Float, also on "
                                                    "two Ints)"
                                                  : ""));
                continue;
            }
            expr_cells_.emplace_back(t->node, i);
        }
    }

    // K: Keep, plus every named variable of Pre that Eff uses too (values flow by name).
    void elaborate_keep() {
        declare_all(kc_, keep_, true);
        if (!src_.span_form) {
            for (const auto& name : lc_.generator_names()) {
                auto g = lc_.generator(name);
                auto h = rc_.generator(name);
                if (g->first.kind == Term::Kind::Value && h && h->first.kind == Term::Kind::Value &&
                    !kc_.generator(name)) {
                    kc_.declare_value(name, lc_.value_type(g->first.node), g->second);
                }
            }
        }
        equations_all(kc_, keep_, true, nullptr);
    }

    // l : K -> L and r : K -> R, fixed by names; l monic; R's new parts completed.
    bool legs(rewrite::Rule& rule) {
        hom::HomSearchOptions lopt, ropt;
        bool names_ok = bind_names(kc_, lc_, lmap_, keep_name_, pre_name_, lopt);
        names_ok = bind_names(kc_, rc_, rmap_, keep_name_, eff_name_, ropt) && names_ok;
        if (!names_ok) {
            return false;
        }
        auto l =
            unique_morphism(rule.K, rule.L, lopt,
                            fmt::format("l : {} -> {}", keep_name_, pre_name_), src_.name_range);
        auto r =
            unique_morphism(rule.K, rule.R, ropt,
                            fmt::format("r : {} -> {}", keep_name_, eff_name_), src_.name_range);
        if (!l || !r || !check_monic(rule, *l) || !complete_created(rule.R, *r, src_.name_range)) {
            return false;
        }
        rule.l = std::move(*l);
        rule.r = std::move(*r);
        return true;
    }

    bool check_monic(const rewrite::Rule& rule, const hom::ACSetMorphism& l) {
        for (std::uint32_t o = 0; o < schema_->num_obs(); ++o) {
            const auto& c = l.components[o];
            for (Part a = 0; a < c.size(); ++a) {
                for (Part b = a + 1; b < c.size(); ++b) {
                    if (c[a] == c[b]) {
                        sink_->error(src_.name_range,
                                     fmt::format("l is not monic: {} parts '{}' and '{}' both "
                                                 "go to part '{}' of {}",
                                                 keep_name_, rule.K.part_label(ObId(o), a),
                                                 rule.K.part_label(ObId(o), b),
                                                 rule.L.part_label(ObId(o), c[a]), pre_name_));
                        return false;
                    }
                }
            }
        }
        return true;
    }

    // An application condition: N = Pre ∪ the condition's statements; n : L -> N by names.
    bool condition(rewrite::Rule& rule, const RuleBlock& b) {
        Colimit nc(schema_, ctx_.inferred_kinds(*schema_));
        nc.allow_redeclare();
        declare_all(nc, pre_, false);
        declare_all(nc, &b, true);
        equations_all(nc, pre_, false, nullptr);
        equations_all(nc, &b, true, nullptr);
        with_sink(false, [&] {
            for (auto& [st, e] : translated_) {
                ValueKind k = ValueKind::Unknown;
                translate(nc, value_side(*st), k, *sink_);
            }
        });
        if (failed()) {
            return false;
        }
        ACSet N = nc.build_partial();
        hom::HomSearchOptions nopt;
        if (!bind_names(lc_, nc, nullptr, pre_name_, b.name, nopt)) {
            return false;
        }
        auto n = unique_morphism(rule.L, N, nopt, fmt::format("n : {} -> {}", pre_name_, b.name),
                                 b.range);
        if (!n) {
            return false;
        }
        rule.conditions.push_back(
            rewrite::ApplicationCondition{fmt::format("{} {}", b.name, rule.conditions.size() + 1),
                                          b.name == "NAC", std::move(N), std::move(*n), b.range});
        return true;
    }

    // Parameters: the header's list, else L's named entities (objects without homs out).
    void parameters(rewrite::Rule& rule) {
        if (src_.has_params) {
            std::map<std::string, SourceRange> seen;
            for (const Expr* p : src_.params) {
                auto g = p->kind == Expr::Kind::Name ? lc_.generator(p->text) : std::nullopt;
                if (!g || g->first.kind != Term::Kind::Part) {
                    sink_->error(p->range, fmt::format("parameter '{}' is not a part generator of "
                                                       "{}",
                                                       to_string(*p), pre_name_));
                    continue;
                }
                if (!new_parameter(seen, *p, *sink_)) {
                    continue;
                }
                rule.parameters.push_back(
                    {p->text, lc_.part_ob(g->first.node), lc_.built_part(g->first.node)});
            }
            return;
        }
        for (const auto& name : lc_.generator_names()) {
            auto g = lc_.generator(name);
            if (g->first.kind == Term::Kind::Part &&
                schema_->homs_from(lc_.part_ob(g->first.node)).empty()) {
                rule.parameters.push_back(
                    {name, lc_.part_ob(g->first.node), lc_.built_part(g->first.node)});
            }
        }
    }

    // The expressions of Eff, on the variables of R they compute.
    void effect_exprs(rewrite::Rule& rule) {
        rule.exprs.resize(schema_->num_attr_types());
        for (std::uint32_t t = 0; t < schema_->num_attr_types(); ++t) {
            rule.exprs[t].resize(rule.R.num_vars(AttrTypeId(t)));
        }
        for (auto [node, i] : expr_cells_) {
            Value v = rc_.built_value(node);
            const Expr* st = translated_[i].first;
            if (!v.is_var()) {
                sink_->error(st->range, fmt::format("'{}' is also given the constant {}; an "
                                                    "attribute is computed or constant, not "
                                                    "both",
                                                    to_string(st->args[0]), v.to_string()));
                continue;
            }
            rule.exprs[rc_.value_type(node).index()][v.var_index()] =
                std::move(translated_[i].second);
        }
    }

    // What rewrite::check_rule finds, located at the variable it names when it names one.
    void check(const rewrite::Rule& rule) {
        for (const auto& problem : rewrite::check_rule(rule)) {
            SourceRange at = src_.name_range;
            if (problem.kind == rewrite::RuleProblemKind::UnboundVariable ||
                problem.kind == rewrite::RuleProblemKind::ExprOnBoundVariable) {
                std::string vname(rule.R.var_name(problem.type, problem.var));
                if (auto g = rc_.generator(vname)) {
                    at = g->second;
                }
            }
            sink_->error(at, fmt::format("in rule '{}': {}", src_.name, problem.message));
        }
    }

    // Runs fn with diagnostics going nowhere unless `loud`: rule blocks are elaborated into
    // several states (Pre into L and into each NAC), and each error should be reported once.
    template <class Fn>
    void with_sink(bool loud, Fn&& fn) {
        DiagnosticSink quiet(ctx_.sources);
        DiagnosticSink* saved = sink_;
        if (!loud) {
            sink_ = &quiet;
        }
        fn();
        sink_ = saved;
    }

    void declare_all(Colimit& c, const RuleBlock* b, bool loud) {
        if (b == nullptr) {
            return;
        }
        with_sink(loud, [&] {
            for (const auto& st : *b->body) {
                if (st.is_binary("::")) {
                    c.declare(st, *sink_);
                }
            }
        });
    }

    // The equations of a block; expression statements are left to the caller (`exprs`), and
    // rejected where none is allowed.
    void equations_all(Colimit& c, const RuleBlock* b, bool loud, std::vector<const Expr*>* exprs) {
        if (b == nullptr) {
            return;
        }
        with_sink(loud, [&] {
            for (const auto& st : *b->body) {
                if (st.is_binary("::")) {
                    continue;
                }
                if (is_expression_statement(st)) {
                    if (exprs != nullptr) {
                        exprs->push_back(&st);
                    } else {
                        sink_->error(st.range,
                                     fmt::format("an attribute computed by an expression may "
                                                 "only be given in the effect block, found '{}' "
                                                 "in '{}'",
                                                 to_string(st), b->name));
                    }
                    continue;
                }
                if (st.is_binary("==")) {
                    c.equation(st, *sink_);
                } else {
                    sink_->error(st.range, fmt::format("expected a generator (x::Block) or an "
                                                       "equation (f(x) == y), found '{}'",
                                                       to_string(st)));
                }
            }
        });
    }

    // Initial bindings from `from`'s generators to `to`'s: by equal names, or by the statements
    // `k => l` of an explicit map block (the slide form's l and r). False after an error.
    bool bind_names(Colimit& from, Colimit& to, const RuleBlock* map, const std::string& from_name,
                    const std::string& to_name, hom::HomSearchOptions& opt) {
        bool ok = true;
        auto bind = [&](const std::string& a, SourceRange a_range, const std::string& b,
                        SourceRange b_range) {
            auto ga = from.generator(a);
            auto gb = to.generator(b);
            if (!ga) {
                sink_->error(a_range, fmt::format("'{}' is not a generator of {}", a, from_name));
                ok = false;
                return;
            }
            if (!gb) {
                sink_->error(b_range,
                             fmt::format("{} {} '{}' is not in {}", from_name,
                                         ga->first.kind == Term::Kind::Part ? "part" : "variable",
                                         b, to_name));
                ok = false;
                return;
            }
            const Term& ta = ga->first;
            const Term& tb = gb->first;
            if (ta.kind != tb.kind || (ta.kind == Term::Kind::Part
                                           ? from.part_ob(ta.node) != to.part_ob(tb.node)
                                           : from.value_type(ta.node) != to.value_type(tb.node))) {
                sink_->error(b_range,
                             fmt::format("'{}' of {} is {} but '{}' of {} is {}", a, from_name,
                                         from.describe(ta), b, to_name, to.describe(tb)));
                ok = false;
                return;
            }
            if (ta.kind == Term::Kind::Part) {
                opt.bind(from.part_ob(ta.node), from.built_part(ta.node), to.built_part(tb.node));
            } else {
                Value va = from.built_value(ta.node);
                if (va.is_var()) {
                    opt.bind_var(from.value_type(ta.node), va.var_index(), to.built_value(tb.node));
                }
            }
        };
        if (map == nullptr) {
            for (const auto& name : from.generator_names()) {
                auto g = from.generator(name);
                bind(name, g->second, name, g->second);
            }
            return ok;
        }
        for (const auto& st : *map->body) {
            if (!st.is_binary("=>") || st.args[0].kind != Expr::Kind::Name ||
                st.args[1].kind != Expr::Kind::Name) {
                sink_->error(st.range, fmt::format("expected 'name => name' (a generator of {} "
                                                   "and its image in {}), found '{}'",
                                                   from_name, to_name, to_string(st)));
                ok = false;
                continue;
            }
            bind(st.args[0].text, st.args[0].range, st.args[1].text, st.args[1].range);
        }
        return ok;
    }

    // The unique morphism from -> to with the given initial bindings, or a located error.
    std::optional<hom::ACSetMorphism> unique_morphism(const ACSet& from, const ACSet& to,
                                                      hom::HomSearchOptions opt,
                                                      const std::string& what, SourceRange at) {
        opt.max_results = 2;
        auto res = hom::find_homomorphisms(from, to, opt);
        if (!res.error.empty()) {
            sink_->error(at, fmt::format("{} cannot be found: {}", what, res.error));
            return std::nullopt;
        }
        if (res.morphisms.empty()) {
            sink_->error(
                at, fmt::format("{} does not exist: {}", what, why_no_morphism(from, to, opt)));
            return std::nullopt;
        }
        if (res.morphisms.size() > 1) {
            sink_->error(at, fmt::format("{} is not unique: the names leave a choice; name the "
                                         "parts of the smaller block so that each has one image",
                                         what));
            return std::nullopt;
        }
        return std::move(res.morphisms[0]);
    }

    // Gives the parts R creates (outside r's image) a value for every attribute and a part for
    // every hom they leave unset, as in a free instance: a fresh unknown, a fresh part.
    bool complete_created(ACSet& r_state, const hom::ACSetMorphism& r, SourceRange at) {
        const Schema& s = r_state.schema();
        std::vector<std::pair<ObId, Part>> work;
        auto created = colimit::parts_outside_image(r, r_state);
        for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
            for (Part p : created[o]) {
                work.emplace_back(ObId(o), p);
            }
        }
        std::size_t fresh = 0;
        while (!work.empty()) {
            auto [ob, p] = work.back();
            work.pop_back();
            for (AttrId a : s.attrs_from(ob)) {
                if (r_state.subpart(a, p).is_unset()) {
                    r_state.set_subpart(a, p, r_state.add_var(s.attr(a).codom));
                }
            }
            for (HomId f : s.homs_from(ob)) {
                if (r_state.subpart(f, p) == kNoPart) {
                    if (++fresh > ctx_.options.max_fresh_parts) {
                        sink_->error(at, fmt::format("the effect creates infinitely many parts "
                                                     "(hom '{}' keeps needing new parts)",
                                                     s.hom(f).name));
                        return false;
                    }
                    ObId c = s.hom(f).codom;
                    Part q = r_state.add_part(c);
                    r_state.set_subpart(f, p, q);
                    work.emplace_back(c, q);
                }
            }
        }
        return true;
    }

    Elaborator& ctx_;
    const RuleSource& src_;
    const std::shared_ptr<Schema>& schema_;
    // Where diagnostics go now: the elaborator's sink, or a quiet one (with_sink).
    DiagnosticSink* sink_;
    std::size_t errors_;
    std::string pre_name_, keep_name_, eff_name_;
    const RuleBlock *pre_ = nullptr, *keep_ = nullptr, *eff_ = nullptr, *lmap_ = nullptr,
                    *rmap_ = nullptr;
    std::vector<const RuleBlock*> conds_;
    Colimit lc_, rc_, kc_; // the presentations of L, R and K
    // Eff's expression statements, translated over L, with the kind each gives.
    std::vector<std::pair<const Expr*, rewrite::AttrExpr>> translated_;
    std::vector<ValueKind> kinds_;
    std::vector<std::pair<std::uint32_t, std::size_t>> expr_cells_; // R value node, index
};

} // namespace

bool new_parameter(std::map<std::string, SourceRange>& seen, const Expr& p, DiagnosticSink& sink) {
    auto [it, fresh] = seen.emplace(p.text, p.range);
    if (!fresh) {
        auto& d = sink.error(p.range, fmt::format("parameter '{}' is given twice", p.text));
        d.notes.emplace_back(it->second, "first given here");
    }
    return fresh;
}

rewrite::RulePtr elaborate_rule(Elaborator& ctx, const RuleSource& src) {
    return RuleElaboration(ctx, src).run();
}

void elaborate_top_rule(Elaborator& ctx, const MacroCall& form, bool imported) {
    RuleSource src;
    if (!rule_source(ctx, form, form.assigned, form.assigned_range, nullptr, src)) {
        return;
    }
    auto rule = elaborate_rule(ctx, src);
    if (!rule || !ctx.claim_name(src.name, src.name_range)) {
        return;
    }
    Declaration d = new_declaration(DeclKind::Rule, src.name, src.name_range, imported, src.schema);
    d.rule = rule;
    ctx.module.add(std::move(d));
}

} // namespace catplan::lang::detail
