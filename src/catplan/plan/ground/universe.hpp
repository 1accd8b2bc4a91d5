#pragma once
// The ground task while it is being built (compile.cpp): the objects, atoms and variables found so
// far, with the values each variable has reached in the relaxed exploration (every value of a
// variable's domain has been reached; presence variables keep which of absent and present has),
// and an index from a hom's target back to the objects and atoms that may point there.
// Internal to the ground compiler.

#include "catplan/plan/entities.hpp"
#include "catplan/plan/ground/task.hpp"
#include "catplan/plan/limits.hpp"

#include <unordered_map>

namespace catplan::plan::ground {

enum class ObKind : std::uint8_t {
    Entities, // every part an entity
    Slots,    // entities and slots (homs point into the object)
    Atoms,    // atoms (nothing points into the object)
};

/// An L part's image candidates, or a hom's pointing parts, as Images.
using Images = std::vector<Image>;

class Universe {
public:
    Universe(Task& task, const Entities& entities, Budget& budget);

    Task& task;
    const schema::Schema& s;
    const Entities& entities;
    Budget& budget;
    std::vector<ObKind> kind;            // per ob
    std::vector<std::uint32_t> position; // per hom and per attr: its index among its ob's

    /// Adds an object (an entity, or slot number `slot` when initial is kNoPart) with cells.
    ObjectId add_object(ObId ob, Part initial, std::uint32_t slot);
    /// Sets a static hom value of an object (indexed for pointing).
    void set_static_hom(ObjectId o, HomId f, ObjectId target);
    /// Makes a cell of an object a variable (its static value, if any, becomes its first value).
    void make_dynamic_hom(ObjectId o, HomId f);
    void make_dynamic_attr(ObjectId o, AttrId a);

    /// The atom with these values, added (absent, unreached) when new.
    AtomId intern(Atom atom);

    /// The index of a value in a variable's domain, added (and reached) when new; a second
    /// return value says whether it was new.
    std::pair<std::uint32_t, bool> hom_value(VarId var, ObjectId target);
    std::pair<std::uint32_t, bool> attr_value(VarId var, const Value& value);
    /// Marks a presence value (0 or 1) reached; whether it was new.
    bool reach_presence(VarId var, std::uint32_t value);
    bool reached(VarId var, std::uint32_t value) const;

    /// The index of a value in a variable's domain, or kNone.
    std::uint32_t find_hom_value(VarId var, ObjectId target) const;
    std::uint32_t find_attr_value(VarId var, const Value& value) const;

    /// The objects and atoms whose hom f may point to target.
    const Images& pointing(HomId f, ObjectId target) const;

    /// The images an L part of ob may take: the objects, or the atoms, of ob.
    Images candidates(ObId ob) const;

    /// Per variable, its initial value (variables made later start at 0: absent).
    std::vector<std::uint32_t> initial_values;

private:
    VarId add_var(Variable v);
    void point(HomId f, ObjectId target, Image from);

    std::unordered_map<std::uint64_t, std::vector<AtomId>> atom_index_;
    std::vector<std::vector<char>> presence_reached_; // per variable (empty for Hom, Attr)
    std::vector<std::unordered_map<std::uint64_t, std::vector<std::uint32_t>>> value_index_;
    std::vector<std::unordered_map<ObjectId, Images>> pointing_; // per hom
    std::vector<std::vector<AtomId>> atoms_of_;                  // per ob
};

/// A hash of an atom's values.
std::uint64_t atom_hash(const Atom& a);

} // namespace catplan::plan::ground
