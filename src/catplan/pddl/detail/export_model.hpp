#pragma once
// How export.cpp reads a catplan domain as PDDL (export.hpp says what the reading means): the
// schema's entity and fact objects, its is-a components and their PDDL types, the attributes and
// how each is written, and the *things* of a state (its entity parts glued along is-a homs), each
// one PDDL object, one marker, or one action parameter.

#include "catplan/acset/acset.hpp"
#include "catplan/base/result.hpp"
#include "catplan/plan/domain.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace catplan::pddl::detail {

using acset::ACSet;
using schema::Schema;

/// Names PDDL accepts: letters, digits, '-' and '_', starting with a letter (else `fallback`
/// is put in front).
std::string pddl_name(std::string_view s, std::string_view fallback);

/// PDDL names compared as PDDL compares them (case-insensitively); `take` makes a name unique.
class NameSet {
public:
    /// Whether the name (in any case) is taken.
    bool taken(std::string_view name) const;
    /// `want`, or `want_2`, `want_3`, ... whichever is free first; reserves it.
    std::string take(std::string_view want);

private:
    std::set<std::string> lowered_;
};

/// How an attribute is written.
enum class AttrUse : std::uint8_t {
    Bool,   // a unary predicate: true = the fact holds
    Name,   // the importer's name attribute: a concrete value pins the part to that object
    Values, // finitely many values, read by a rule or the goal: a unary predicate per value
    Dropped // never read: left out (noted)
};

struct AttrReading {
    AttrUse use = AttrUse::Dropped;
    /// Values: each value's predicate, by the value's display form.
    std::map<std::string, std::string> value_predicate;
    std::string predicate; // Bool: its predicate
};

/// An is-a component: the entity objects linked by is-a homs.
struct Component {
    std::vector<ObId> obs;
    bool forest = true;    // every object has at most one is-a hom: PDDL types
    std::string type_name; // when not a forest: the one PDDL type of its things
};

/// The schema read as PDDL, with the names of the domain's predicates and types.
struct Reading {
    const Schema* schema = nullptr;
    std::vector<bool> entity;                 // by object
    std::vector<std::optional<HomId>> parent; // forest: the is-a hom of an object
    std::vector<std::size_t> component;       // by entity object
    std::vector<Component> components;
    std::vector<ObId> facts;                   // fact objects (predicates), in order
    std::vector<AttrReading> attrs;            // by attribute
    std::vector<std::string> type_of_ob;       // forest objects: their type's name
    std::vector<std::string> member_predicate; // non-forest objects: `(is_O ?x)`
    std::vector<std::string> fact_predicate;   // fact objects: their predicate's name
    std::vector<std::string> notes;            // what the reading leaves out

    /// The PDDL type of an argument that is a part of `ob`.
    const std::string& arg_type(ObId ob) const;
    /// Whether x is an is-a hom (between entity objects).
    bool is_a(HomId f) const;
};

/// Reads the schema and the attributes' uses (the values a rule, the initial state or the goal
/// holds, and whether a rule or the goal reads them); fails when the schema is not expressible.
Result<Reading> read_schema(const plan::Domain& domain, const plan::Problem* problem,
                            NameSet& names);

/// A thing: entity parts glued along is-a homs; one PDDL object, marker or parameter.
struct Thing {
    std::vector<Part> part; // by object: the thing's part, or kNoPart
    std::string shape;      // its objects' names joined by '+', e.g. "Object+Receptacle"
    std::size_t component = 0;
    ObId bottom;         // forest components: the most specific object (the thing's type)
    ObId first;          // the first object (in declaration order) it has a part of
    std::string name;    // its PDDL name (without `?`); empty for a marker
    bool pinned = false; // named by a concrete name attribute: a constant
    bool marker = false; // a part of a marker: not a PDDL object
    bool named = false;  // some part has a name (or a pin)
};

/// The things of a state.
struct Things {
    std::vector<Thing> things;
    /// By object, by part: the thing it belongs to.
    std::vector<std::vector<std::size_t>> of;

    /// The thing part p of ob belongs to, or kNoThing for a part of a fact object.
    std::size_t at(ObId ob, Part p) const {
        return p < of[ob.index()].size() ? of[ob.index()][p] : kNoThing;
    }

    static constexpr std::size_t kNoThing = static_cast<std::size_t>(-1);
};

/// The things of x: fails when a thing has two parts of one object or (in a forest component) is
/// not a chain. Names: the pin, else the first named part's name, else `<Ob>_<k>`; unique among
/// `names` (`?` names, within a rule, are unique among themselves). `marker_shapes`: an unnamed
/// thing of one of these shapes is a marker.
Result<Things> find_things(const Reading& rd, const ACSet& x,
                           const std::set<std::string>& marker_shapes, NameSet& names,
                           std::string_view what);

/// The PDDL type of a thing.
std::string thing_type(const Reading& rd, const Thing& t);

} // namespace catplan::pddl::detail
