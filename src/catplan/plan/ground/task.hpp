#pragma once
// The ground task: a C-set planning problem compiled once into finite-domain variables and ground
// actions (compile.hpp builds it), so that the search works on packed states compared exactly.
//
// Objects. The parts a state is made of fall into three kinds:
//   - entities (entities.hpp): initial parts that persist in every reachable state;
//   - slots: places for the other parts of an object that homs point into (the paper's marker
//     block); a slot holds at most one part at a time and may be empty;
//   - atoms: parts of an object nothing points into (On, PDDL's predicates), each described by its
//     hom values (objects) and attribute values, so that one atom is one possible part. A state
//     holds an atom or not (set semantics: two equal parts are one state the task cannot
//     represent, see Action::creates).
// An object is an entity or a slot; homs point to objects, never to atoms.
//
// Variables. Each hom value of an object that some rule can change is one variable (its values
// are objects or "unset"), likewise each attribute value (concrete values, "an unknown" or
// unset); a slot has a presence variable; an atom a presence variable. Values that no rule changes
// are static and stored with the object.
//
// Actions. A ground action is a rule and a match: the object or atom each L part maps to, and the
// value each L variable binds. Its preconditions are facts (var = value); `forbidden` are facts
// that must not hold (the dangling condition on multi-valued variables); `nacs` lists, per
// extension of the match along a negative application condition, the facts under which it holds;
// its effects assign variables. An action whose result the task cannot represent (a second equal
// atom of an object that is not one of the rule's relations, no free slot, an unknown value copied
// to another cell) is an *exit*: it is recognised when applicable but never applied, and the search
// says how often that happened.

#include "catplan/acset/value.hpp"
#include "catplan/base/id.hpp"
#include "catplan/plan/domain.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace catplan::plan::ground {

using acset::Value;
using VarId = std::uint32_t;
using ObjectId = std::uint32_t;
using AtomId = std::uint32_t;
using ActionId = std::uint32_t;

inline constexpr std::uint32_t kNone = UINT32_MAX;

/// A variable and one of its values.
struct Fact {
    VarId var = 0;
    std::uint32_t value = 0;

    friend bool operator==(const Fact&, const Fact&) = default;
    friend auto operator<=>(const Fact&, const Fact&) = default;
};

/// An entity or a slot.
struct Object {
    ObId ob;
    Part initial = kNoPart; // an entity's initial part; kNoPart for a slot
    std::uint32_t slot = 0; // a slot's index among its object's slots
    VarId presence = kNone; // a slot's presence variable

    bool is_slot() const { return initial == kNoPart; }
};

/// A cell (a hom or attribute value of an object): its variable, or its static value.
struct Cell {
    VarId var = kNone;       // kNone: static
    ObjectId target = kNone; // a static hom value (kNone: unset)
    Value value;             // a static attribute value
};

/// A part of an object nothing points into, described by its values.
struct Atom {
    ObId ob;
    std::vector<ObjectId> homs; // per hom of ob (schema order), the object it points to, or kNone
    std::vector<Value> attrs;   // per attribute of ob (schema order)
    VarId var = kNone;          // its presence variable

    friend bool operator==(const Atom& a, const Atom& b) {
        return a.ob == b.ob && a.homs == b.homs && a.attrs == b.attrs;
    }
};

/// What a variable is about.
struct Variable {
    enum class Kind : std::uint8_t { Presence, Hom, Attr, Atom };
    Kind kind = Kind::Presence;
    std::uint32_t owner = 0;       // the object (Presence, Hom, Attr) or the atom (Atom)
    std::uint32_t index = 0;       // the HomId or AttrId
    std::vector<ObjectId> targets; // Hom: the value's object (kNone: unset)
    std::vector<Value> values;     // Attr: the value (Value() unset, a variable: an unknown)

    /// Number of values (Presence and Atom: 2, absent and present).
    std::uint32_t size() const;
};

/// "an unknown": the one value the task gives every attribute variable of a state (no two cells
/// share an unknown, compile.hpp checks it).
inline constexpr Value kUnknown = Value::var(0);

/// The binding of a pattern variable whose value nothing reads (it occurs once and the rule
/// passes it through unchanged, or it is a goal's): any value it is set to will do.
inline constexpr Value kAny = Value::var(1);

/// Where an L part of a ground action lands.
struct Image {
    bool atom = false;
    std::uint32_t id = kNone; // an ObjectId or an AtomId
};

struct Action {
    std::uint32_t rule = 0;
    /// Per object of the schema, per L part: its image.
    std::vector<std::vector<Image>> match;
    /// Per attribute type, per L variable: the value it binds.
    std::vector<std::vector<Value>> bindings;
    std::vector<Fact> pre;               // sorted by variable, one fact per variable
    std::vector<Fact> forbidden;         // none of these holds
    std::vector<std::vector<Fact>> nacs; // the action does not apply when every fact of one holds
    std::vector<Fact> eff;               // sorted by variable
    std::vector<VarId> creates; // atom variables it sets present that it did not need present
    std::string exit;           // not empty: why applying it leaves the task
    int cost = 1;               // what the problem says the step costs (Problem::step_cost)
};

/// The largest cost of one ground action the task keeps; a problem with a larger one is searched
/// counting steps (g and h are ints summed over a plan).
inline constexpr std::int64_t kMaxActionCost = 100'000;

struct Task {
    ProblemPtr problem;
    std::vector<Object> objects;
    std::vector<std::vector<ObjectId>> objects_of; // per ob
    std::vector<std::vector<Cell>> homs, attrs;    // per object, per hom / attribute of its ob
    std::vector<Atom> atoms;
    std::vector<Variable> vars;
    std::vector<std::uint32_t> initial; // per variable
    /// The goal: a state satisfies it when every fact of one term holds.
    std::vector<std::vector<Fact>> goal;
    std::vector<Action> actions;
    /// Groups of atom variables of which at most one is present in every reachable state
    /// (mutexes.hpp); the state packer stores disjoint ones in one field each.
    std::vector<std::vector<VarId>> mutex_groups;
    /// Whether every action costs 1; when not, an A* search counts the costs (ground_search.hpp).
    bool unit_cost = true;
    /// Ground actions left out because the problem gives their step no cost (the step cannot be
    /// taken: a PDDL cost whose function value is missing).
    std::uint64_t uncosted = 0;
    /// Not empty when the problem's costs cannot be counted and each action costs 1 instead:
    /// why (a cost beyond kMaxActionCost, or a negative one).
    std::string costs_ignored;

    /// "isHolding(gripper)", "On(E, D)", "Block#1 exists": for messages and tests.
    std::string describe(VarId var) const;
    /// "isHolding(gripper) = D".
    std::string describe(Fact fact) const;
    /// "unstack(E, D)" (the rule and its parameters' images).
    std::string describe_action(ActionId a) const;
    /// The names of the images of the rule's parameters under the action's match ("E", "D").
    std::vector<std::string> argument_names(const Action& a) const;
    /// The name of an object: its initial part's label, or "Block#2" for a slot.
    std::string object_name(ObjectId o) const;
};

} // namespace catplan::plan::ground
