#include "catplan/rewrite/rule.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/colimit/colimit.hpp"

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace catplan::rewrite {

namespace {

using Op = AttrExpr::Op;

bool is_number(const Value& v) {
    return v.tag() == Value::Tag::Int || v.tag() == Value::Tag::Float;
}

double as_double(const Value& v) {
    return v.tag() == Value::Tag::Int ? static_cast<double>(v.as_int()) : v.as_float();
}

Result<Value> arithmetic(Op op, const Value& a, const Value& b) {
    if (op == Op::Mul && a.tag() == Value::Tag::String && b.tag() == Value::Tag::String) {
        return Value::string(std::string(a.as_string()) + std::string(b.as_string()));
    }
    if (!is_number(a) || !is_number(b)) {
        return fail(fmt::format("arithmetic on {} and {}", a.to_string(), b.to_string()));
    }
    // Int with Int stays Int and is checked: a result outside 64 bits is an error, never a
    // wrapped value. `/` gives a Float, also on two Ints, as in Julia.
    if (a.tag() == Value::Tag::Int && b.tag() == Value::Tag::Int && op != Op::Div) {
        std::int64_t x = a.as_int(), y = b.as_int(), z = 0;
        bool overflow = op == Op::Add   ? __builtin_add_overflow(x, y, &z)
                        : op == Op::Sub ? __builtin_sub_overflow(x, y, &z)
                                        : __builtin_mul_overflow(x, y, &z);
        if (overflow) {
            return fail(fmt::format("Int overflow: {} {} {} is outside the range of Int", x,
                                    op == Op::Add   ? "+"
                                    : op == Op::Sub ? "-"
                                                    : "*",
                                    y));
        }
        return Value::integer(z);
    }
    double x = as_double(a), y = as_double(b);
    switch (op) {
    case Op::Add:
        return Value::real(x + y);
    case Op::Sub:
        return Value::real(x - y);
    case Op::Mul:
        return Value::real(x * y);
    default:
        if (y == 0.0) {
            return fail("division by zero");
        }
        return Value::real(x / y);
    }
}

Result<Value> compare(Op op, const Value& a, const Value& b) {
    if (op == Op::Eq || op == Op::Ne) {
        bool eq = is_number(a) && is_number(b) && a.tag() != b.tag() ? as_double(a) == as_double(b)
                                                                     : a == b;
        return Value::boolean(op == Op::Eq ? eq : !eq);
    }
    int c = 0;
    if (a.tag() == Value::Tag::Int && b.tag() == Value::Tag::Int) {
        // Exactly: beyond 2^53 two Ints can convert to one double.
        c = a.as_int() < b.as_int() ? -1 : (a.as_int() > b.as_int() ? 1 : 0);
    } else if (is_number(a) && is_number(b)) {
        double x = as_double(a), y = as_double(b);
        c = x < y ? -1 : (x > y ? 1 : 0);
    } else if (a.tag() == Value::Tag::String && b.tag() == Value::Tag::String) {
        c = a.as_string().compare(b.as_string());
    } else {
        return fail(fmt::format("cannot order {} and {}", a.to_string(), b.to_string()));
    }
    switch (op) {
    case Op::Lt:
        return Value::boolean(c < 0);
    case Op::Le:
        return Value::boolean(c <= 0);
    case Op::Gt:
        return Value::boolean(c > 0);
    default:
        return Value::boolean(c >= 0);
    }
}

} // namespace

Result<Value> evaluate(const AttrExpr& e,
                       const std::function<Value(AttrTypeId, std::uint32_t)>& input) {
    switch (e.op) {
    case Op::Const:
        return e.constant;
    case Op::Input: {
        Value v = input(e.input_type, e.input_var);
        if (!v.is_concrete()) {
            return fail("the expression reads a value the match left unknown");
        }
        return v;
    }
    default:
        break;
    }
    std::vector<Value> args;
    for (const auto& a : e.args) {
        auto v = evaluate(a, input);
        if (!v) {
            return v;
        }
        args.push_back(*v);
    }
    auto need_bool = [&](std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            if (args[i].tag() != Value::Tag::Bool) {
                return false;
            }
        }
        return true;
    };
    switch (e.op) {
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
        return arithmetic(e.op, args[0], args[1]);
    case Op::Concat:
        if (args[0].tag() != Value::Tag::String || args[1].tag() != Value::Tag::String) {
            return fail("concatenation of non-strings");
        }
        return Value::string(std::string(args[0].as_string()) + std::string(args[1].as_string()));
    case Op::Neg:
        if (args[0].tag() == Value::Tag::Int) {
            std::int64_t x = args[0].as_int(), z = 0;
            if (__builtin_sub_overflow(std::int64_t{0}, x, &z)) {
                return fail(fmt::format("Int overflow: -({}) is outside the range of Int", x));
            }
            return Value::integer(z);
        }
        if (args[0].tag() == Value::Tag::Float) {
            return Value::real(-args[0].as_float());
        }
        return fail(fmt::format("negation of {}", args[0].to_string()));
    case Op::Not:
        if (!need_bool(1)) {
            return fail("! of a non-Bool value");
        }
        return Value::boolean(!args[0].as_bool());
    case Op::And:
    case Op::Or:
        if (!need_bool(2)) {
            return fail("&& or || of a non-Bool value");
        }
        return Value::boolean(e.op == Op::And ? args[0].as_bool() && args[1].as_bool()
                                              : args[0].as_bool() || args[1].as_bool());
    default:
        return compare(e.op, args[0], args[1]);
    }
}

namespace {

// Per object, the parts of L, K and R (what a rule's anatomy was computed from).
std::vector<std::size_t> part_counts(const Rule& rule) {
    std::vector<std::size_t> counts;
    for (std::uint32_t o = 0; o < rule.L.schema().num_obs(); ++o) {
        for (const ACSet* x : {&rule.L, &rule.K, &rule.R}) {
            counts.push_back(x->num_parts(ObId(o)));
        }
    }
    return counts;
}

bool same_counts(const Rule& rule, const std::vector<std::size_t>& counts, ObId ob) {
    std::size_t i = 3 * std::size_t{ob.index()};
    return counts[i] == rule.L.num_parts(ob) && counts[i + 1] == rule.K.num_parts(ob) &&
           counts[i + 2] == rule.R.num_parts(ob);
}

} // namespace

const Rule::Anatomy& Rule::anatomy(ObId ob) const {
    if (const Anatomy* known = anatomy_.peek()) {
        CATPLAN_ASSERT(same_counts(*this, known->counts, ob),
                       "a rule's states changed after its deleted and created parts were read");
        return *known;
    }
    return anatomy_.get([&] {
        return Anatomy{colimit::parts_outside_image(l, L), colimit::parts_outside_image(r, R),
                       part_counts(*this)};
    });
}

std::vector<RuleProblem> check_rule(const Rule& rule) {
    std::vector<RuleProblem> problems;
    for (const auto& f : hom::naturality_failures(rule.l, rule.K, rule.L)) {
        problems.push_back(
            {RuleProblemKind::LeftNotNatural, AttrTypeId(), 0,
             "l : Keep -> Pre is not a morphism: " + hom::describe(f, rule.K, rule.L)});
    }
    for (const auto& f : hom::naturality_failures(rule.r, rule.K, rule.R)) {
        problems.push_back(
            {RuleProblemKind::RightNotNatural, AttrTypeId(), 0,
             "r : Keep -> Eff is not a morphism: " + hom::describe(f, rule.K, rule.R)});
    }
    if (problems.empty() && !hom::is_monic(rule.l, rule.K, rule.L)) {
        problems.push_back({RuleProblemKind::LeftNotMonic, AttrTypeId(), 0,
                            "l : Keep -> Pre is not monic: two kept parts are one part of Pre"});
    }
    if (!problems.empty()) {
        return problems;
    }
    const auto& s = rule.R.schema();
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        std::vector<bool> bound(rule.R.num_vars(ty), false);
        for (std::uint32_t k = 0; k < rule.K.num_vars(ty); ++k) {
            const Value& v = rule.r.var(ty, k);
            if (v.is_var()) {
                bound[v.var_index()] = true;
            }
        }
        for (std::uint32_t j = 0; j < rule.R.num_vars(ty); ++j) {
            bool has_expr =
                t < rule.exprs.size() && j < rule.exprs[t].size() && rule.exprs[t][j].has_value();
            auto name = rule.R.var_name(ty, j);
            if (bound[j] && has_expr) {
                problems.push_back(
                    {RuleProblemKind::ExprOnBoundVariable, ty, j,
                     fmt::format("variable {} of {} is kept from Pre, so it cannot "
                                 "also be given an expression",
                                 rule.R.value_label(ty, Value::var(j)), s.attr_type(ty).name)});
            } else if (!bound[j] && !has_expr && !name.empty()) {
                problems.push_back(
                    {RuleProblemKind::UnboundVariable, ty, j,
                     fmt::format("variable '{}' of {} in Eff is bound by nothing: bind it in Pre "
                                 "and Keep, or give an expression for it",
                                 name, s.attr_type(ty).name)});
            }
        }
    }
    return problems;
}

std::string Cost::to_string(const std::vector<std::string>& names) const {
    std::vector<std::string> parts;
    if (constant != 0 || terms.empty()) {
        parts.push_back(std::to_string(constant));
    }
    for (const auto& t : terms) {
        std::vector<std::string> args;
        for (const auto& a : t.arguments) {
            auto i = static_cast<std::size_t>(a.parameter);
            args.push_back(a.parameter >= 0
                               ? (i < names.size() ? names[i] : "?")
                               : (a.constant.empty() ? "?" : "\"" + a.constant + "\""));
        }
        parts.push_back(fmt::format("{}({})", t.function, fmt::join(args, ", ")));
    }
    return fmt::format("{}", fmt::join(parts, " + "));
}

} // namespace catplan::rewrite
