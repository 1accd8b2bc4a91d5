#pragma once
// Actions as DPO rewrite rules: a span L <-l- K -r-> R of states (Pre, Keep, Eff), l monic.
//
//        l       r          A match m : L -> X (monic on every object by default) picks where the
//   L <----- K -----> R     rule applies. The parts of L outside l(K) are deleted, the parts of R
//   |m       |        |     outside r(K) are created, and the kept parts are glued to R.
//   v        v        v
//   X <----- Z -----> Y     Z = X - m(L - l(K));   Y = the pushout of R <- K -> Z.
//
// Updates of kept parts (semantics.md "Actions"): parts of Y that come from R take R's values, with
// R's variables replaced by what the match bound through l and r. So a kept part whose attribute is
// a variable in K and a constant in R has that attribute updated (the paper's
// `isClear(underblock) == true`), and one whose attribute is the same variable in L, K and R keeps
// its value. Homs are treated alike: K may leave a hom of a kept part unset (a partial state),
// meaning "the rule redirects it"; R then says where it points (the paper's `isHolding(gripper) ==
// block` with `gripper` kept). Such a hom is not a dangling reference even if its old target is
// deleted, since R replaces it.
//
// Attribute values of created parts: a constant of R, a value bound through K, or an expression
// (AttrExpr) computed from the values the match bound to L's variables. A *named* variable of R
// that none of these binds is a rule-definition error; an unnamed one becomes a fresh unknown (a
// variable) of the result state. An attribute R leaves unset stays unset on a created part (as in
// the pushout) and unchanged on a kept part.
//
// Negative application conditions L -> N: a match is rejected when it extends along L -> N to a
// monic N -> X (PDDL's negative preconditions).

#include "catplan/acset/acset.hpp"
#include "catplan/base/lazy.hpp"
#include "catplan/base/result.hpp"
#include "catplan/base/source.hpp"
#include "catplan/hom/morphism.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace catplan::rewrite {

using acset::ACSet;
using acset::Value;
using hom::ACSetMorphism;

/// An expression computing an attribute value of a created or updated part from the values the
/// match bound to L's variables.
struct AttrExpr {
    enum class Op : std::uint8_t {
        Const, // `constant`
        Input, // the value bound to L's variable `input_var` of type `input_type`
        Add,
        Sub,
        Mul,
        Div,
        Neg,    // arithmetic on Int/Float (Int if both Int, except Div: always Float)
        Concat, // string concatenation (`*` in Julia)
        Not,
        And,
        Or, // Bool
        Eq,
        Ne,
        Lt,
        Le,
        Gt,
        Ge, // comparisons, giving Bool
    };
    Op op = Op::Const;
    Value constant;
    AttrTypeId input_type;
    std::uint32_t input_var = 0;
    std::vector<AttrExpr> args;
    SourceRange range;
};

/// Evaluates an expression; `input(type, var)` gives the value the match bound to an L variable.
/// Fails with a reason on a type error, an Int overflow, a division by zero, or an input that is
/// not concrete.
Result<Value> evaluate(const AttrExpr& e,
                       const std::function<Value(AttrTypeId, std::uint32_t)>& input);

/// An application condition: the match must not (negative) or must (positive) extend along
/// n : L -> N to a monic morphism N -> X.
struct ApplicationCondition {
    std::string name;
    bool negative = true;
    ACSet n_state;
    ACSetMorphism n; // L -> N
    SourceRange range;
};

/// A rule parameter: a named generator of L (`unstack(block, underblock)`).
struct Parameter {
    std::string name;
    ObId ob;
    Part part;
};

/// The action a rule carries out when one action has several rules (a PDDL action's variants,
/// one per identification of its parameters): a step `stack(b, a)` of the action is a step of
/// the rule whose arguments it fits.
struct ActionOf {
    /// One argument of the action: a parameter of the rule, or a part name it must be.
    struct Argument {
        int parameter = -1;   // index into Rule::parameters; -1 for a constant
        std::string constant; // the part name, when parameter < 0
        friend bool operator==(const Argument&, const Argument&) = default;
    };

    std::string name;
    std::vector<Argument> arguments;
    friend bool operator==(const ActionOf&, const ActionOf&) = default;
};

/// What applying a rule costs, when the rule says: a constant and the values a problem gives
/// functions of the step's arguments, summed (PDDL's `(increase (total-cost) 2)` and
/// `(increase (total-cost) (road-length ?from ?to))`; catplan's `cost = 2 + road_length(from,
/// to)`). plan/costs.hpp computes it.
struct Cost {
    /// A function of the step's arguments: `road_length(from, to)`.
    struct Term {
        std::string function;
        /// Each a parameter of the rule or a part name; a parameter -1 with no name is one a
        /// migration lost (the term then has no value).
        std::vector<ActionOf::Argument> arguments;
        friend bool operator==(const Term&, const Term&) = default;
    };

    std::int64_t constant = 0;
    std::vector<Term> terms;

    /// "2 + road_length(from, to)", each parameter called by its name in `names` (the rule's
    /// parameters' names, or a step's arguments), a part name in quotes.
    std::string to_string(const std::vector<std::string>& names) const;
};

/// How a rule treats parts of X that refer to a part it deletes. DPO: the match is rejected (the
/// dangling condition). SPO (single pushout, reference §4.5): they are deleted too, and so on
/// transitively (dangling edges are removed); a match whose cascade would reach a kept part is
/// still rejected, since the rule says that part stays.
enum class Semantics : std::uint8_t { DPO, SPO };

namespace detail {
struct Shape;
}

struct Rule {
    std::string name;
    Semantics semantics = Semantics::DPO;
    ACSet L, K, R;
    ACSetMorphism l; // K -> L, monic
    ACSetMorphism r; // K -> R
    std::vector<ApplicationCondition> conditions;
    /// Per attribute type, per variable of R: the expression giving its value, if any.
    std::vector<std::vector<std::optional<AttrExpr>>> exprs;
    std::vector<Parameter> parameters;
    /// Objects whose parts are facts, determined by their values (PDDL's predicates): a part the
    /// rule creates that equals one already there is merged into it, so adding a fact that holds
    /// changes nothing (detail/relations.hpp).
    std::vector<ObId> relations;
    SourceRange range;
    /// What a step of the rule costs, when it says (nullopt: nothing said, a step counts 1).
    /// Migration carries it to the migrated rule.
    std::optional<Cost> cost;
    /// The action a step of the rule is a step of, when that is not the rule itself (nullopt:
    /// the action is the rule, its arguments the rule's parameters).
    std::optional<ActionOf> action;

    /// A rule with empty states on a schema (to be filled by a builder or the elaborator).
    explicit Rule(const schema::SchemaPtr& s) : L(s), K(s), R(s) {}

    /// The name of the action a step of the rule is a step of.
    const std::string& action_name() const { return action ? action->name : name; }

    /// The number of arguments of that action.
    std::size_t action_arity() const {
        return action ? action->arguments.size() : parameters.size();
    }

    /// The parts of L at ob outside l(K), in increasing order: what the rule deletes.
    const std::vector<Part>& deleted_parts(ObId ob) const {
        return anatomy(ob).deleted[ob.index()];
    }

    /// The parts of R at ob outside r(K), in increasing order: what the rule creates.
    const std::vector<Part>& created_parts(ObId ob) const {
        return anatomy(ob).created[ob.index()];
    }

    /// What matching and application need to know about the rule (detail/shape.hpp), computed
    /// at the first match or application and kept.
    const detail::Shape& shape() const;

private:
    // What the rule deletes and creates, and its shape, computed on first use (base/lazy.hpp: a
    // copy computes its own). A builder fills L, K, R, l and r first; changing them afterwards is
    // a misuse (asserted on the part counts at the object asked about: these are read once per
    // ground action, so the check must not cost more).
    struct Anatomy {
        std::vector<std::vector<Part>> deleted, created;
        std::vector<std::size_t> counts; // per object: parts of L, K, R when computed
    };

    const Anatomy& anatomy(ObId ob) const;

    Lazy<Anatomy> anatomy_;
    Lazy<detail::Shape> shape_;
};

using RulePtr = std::shared_ptr<const Rule>;

enum class RuleProblemKind {
    LeftNotNatural,     // l is not a morphism K -> L (detail: the naturality failure)
    RightNotNatural,    // r is not a morphism K -> R
    LeftNotMonic,       // l identifies two parts of K
    UnboundVariable,    // a named variable of R bound by nothing (type, var)
    ExprOnBoundVariable // an expression given for a variable that K already binds (type, var)
};

struct RuleProblem {
    RuleProblemKind kind;
    AttrTypeId type;       // UnboundVariable, ExprOnBoundVariable
    std::uint32_t var = 0; // the variable of R
    std::string message;   // in words, with names
};

/// Every problem of a rule's definition (empty when the rule is well formed).
std::vector<RuleProblem> check_rule(const Rule& rule);

} // namespace catplan::rewrite
