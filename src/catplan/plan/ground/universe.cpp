#include "catplan/plan/ground/universe.hpp"

#include "catplan/base/hash.hpp"

namespace catplan::plan::ground {

std::uint32_t Variable::size() const {
    switch (kind) {
    case Kind::Presence:
    case Kind::Atom:
        return 2;
    case Kind::Hom:
        return static_cast<std::uint32_t>(targets.size());
    case Kind::Attr:
        return static_cast<std::uint32_t>(values.size());
    }
    CATPLAN_UNREACHABLE("variable kind");
}

std::uint64_t atom_hash(const Atom& a) {
    std::uint64_t h = hash_mix(a.ob.index());
    for (ObjectId t : a.homs) {
        h = hash_combine(h, t);
    }
    for (const auto& v : a.attrs) {
        h = hash_combine(h, v.hash());
    }
    return h;
}

Universe::Universe(Task& t, const Entities& e, Budget& b)
    : task(t), s(t.problem->initial->schema()), entities(e), budget(b) {
    kind.assign(s.num_obs(), ObKind::Atoms);
    position.assign(s.num_homs() + s.num_attrs(), 0);
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        std::uint32_t i = 0;
        for (HomId f : s.homs_from(ob)) {
            position[f.index()] = i++;
        }
        i = 0;
        for (AttrId a : s.attrs_from(ob)) {
            position[s.num_homs() + a.index()] = i++;
        }
    }
    task.objects_of.assign(s.num_obs(), {});
    pointing_.assign(s.num_homs(), {});
    atoms_of_.assign(s.num_obs(), {});
}

VarId Universe::add_var(Variable v) {
    auto id = static_cast<VarId>(task.vars.size());
    bool binary = v.kind == Variable::Kind::Presence || v.kind == Variable::Kind::Atom;
    task.vars.push_back(std::move(v));
    presence_reached_.emplace_back(binary ? 2 : 0, 0);
    value_index_.emplace_back();
    return id;
}

ObjectId Universe::add_object(ObId ob, Part initial, std::uint32_t slot) {
    auto id = static_cast<ObjectId>(task.objects.size());
    Object obj{ob, initial, slot, kNone};
    if (initial == kNoPart) {
        obj.presence = add_var({Variable::Kind::Presence, id, 0, {}, {}});
    }
    task.objects.push_back(obj);
    task.objects_of[ob.index()].push_back(id);
    task.homs.emplace_back(s.homs_from(ob).size());
    task.attrs.emplace_back(s.attrs_from(ob).size());
    return id;
}

void Universe::point(HomId f, ObjectId target, Image from) {
    if (target != kNone) {
        pointing_[f.index()][target].push_back(from);
    }
}

void Universe::set_static_hom(ObjectId o, HomId f, ObjectId target) {
    Cell& c = task.homs[o][position[f.index()]];
    CATPLAN_ASSERT(c.var == kNone, "a static hom value set on a variable");
    c.target = target;
    point(f, target, Image{false, o});
}

void Universe::make_dynamic_hom(ObjectId o, HomId f) {
    Cell& c = task.homs[o][position[f.index()]];
    if (c.var != kNone) {
        return;
    }
    ObjectId initial = c.target;
    c.var = add_var({Variable::Kind::Hom, o, f.index(), {}, {}});
    c.target = kNone;
    // The static value was indexed as pointing already; hom_value must not index it twice.
    auto& var = task.vars[c.var];
    var.targets.push_back(initial);
    value_index_[c.var][initial].push_back(0);
}

void Universe::make_dynamic_attr(ObjectId o, AttrId a) {
    Cell& c = task.attrs[o][position[s.num_homs() + a.index()]];
    if (c.var != kNone) {
        return;
    }
    Value initial = c.value;
    c.var = add_var({Variable::Kind::Attr, o, a.index(), {}, {}});
    c.value = Value();
    attr_value(c.var, initial);
}

AtomId Universe::intern(Atom atom) {
    std::uint64_t h = atom_hash(atom);
    auto& bucket = atom_index_[h];
    for (AtomId id : bucket) {
        if (task.atoms[id] == atom) {
            return id;
        }
    }
    auto id = static_cast<AtomId>(task.atoms.size());
    atom.var = add_var({Variable::Kind::Atom, id, 0, {}, {}});
    std::uint32_t i = 0;
    for (HomId f : s.homs_from(atom.ob)) {
        point(f, atom.homs[i++], Image{true, id});
    }
    atoms_of_[atom.ob.index()].push_back(id);
    task.atoms.push_back(std::move(atom));
    bucket.push_back(id);
    return id;
}

std::pair<std::uint32_t, bool> Universe::hom_value(VarId var, ObjectId target) {
    if (auto i = find_hom_value(var, target); i != kNone) {
        return {i, false};
    }
    auto& v = task.vars[var];
    auto i = static_cast<std::uint32_t>(v.targets.size());
    v.targets.push_back(target);
    value_index_[var][target].push_back(i);
    point(HomId(v.index), target, Image{false, v.owner});
    return {i, true};
}

std::pair<std::uint32_t, bool> Universe::attr_value(VarId var, const Value& value) {
    if (auto i = find_attr_value(var, value); i != kNone) {
        return {i, false};
    }
    auto& v = task.vars[var];
    auto i = static_cast<std::uint32_t>(v.values.size());
    v.values.push_back(value);
    value_index_[var][value.hash()].push_back(i);
    return {i, true};
}

std::uint32_t Universe::find_hom_value(VarId var, ObjectId target) const {
    const auto& idx = value_index_[var];
    auto it = idx.find(target);
    return it == idx.end() ? kNone : it->second.front();
}

std::uint32_t Universe::find_attr_value(VarId var, const Value& value) const {
    const auto& idx = value_index_[var];
    auto it = idx.find(value.hash());
    if (it == idx.end()) {
        return kNone;
    }
    for (std::uint32_t i : it->second) {
        if (task.vars[var].values[i] == value) {
            return i;
        }
    }
    return kNone;
}

bool Universe::reach_presence(VarId var, std::uint32_t value) {
    auto& r = presence_reached_[var];
    if (r[value]) {
        return false;
    }
    r[value] = 1;
    return true;
}

bool Universe::reached(VarId var, std::uint32_t value) const {
    const auto& r = presence_reached_[var];
    return r.empty() ? value < task.vars[var].size() : r[value] != 0;
}

const Images& Universe::pointing(HomId f, ObjectId target) const {
    static const Images kEmpty;
    const auto& m = pointing_[f.index()];
    auto it = m.find(target);
    return it == m.end() ? kEmpty : it->second;
}

Images Universe::candidates(ObId ob) const {
    Images out;
    if (kind[ob.index()] == ObKind::Atoms) {
        for (AtomId a : atoms_of_[ob.index()]) {
            out.push_back({true, a});
        }
    } else {
        for (ObjectId o : task.objects_of[ob.index()]) {
            out.push_back({false, o});
        }
    }
    return out;
}

} // namespace catplan::plan::ground
