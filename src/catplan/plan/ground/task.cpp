#include "catplan/plan/ground/task.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace catplan::plan::ground {

std::string Task::object_name(ObjectId o) const {
    if (o == kNone) {
        return "_";
    }
    const Object& obj = objects[o];
    const auto& x = *problem->initial;
    if (!obj.is_slot()) {
        return x.part_label(obj.ob, obj.initial);
    }
    return fmt::format("{}#{}", x.schema().ob(obj.ob).name, obj.slot + 1);
}

std::string Task::describe(VarId var) const {
    const Variable& v = vars[var];
    const auto& s = problem->initial->schema();
    switch (v.kind) {
    case Variable::Kind::Presence:
        return fmt::format("{} exists", object_name(v.owner));
    case Variable::Kind::Hom:
        return fmt::format("{}({})", s.hom(HomId(v.index)).name, object_name(v.owner));
    case Variable::Kind::Attr:
        return fmt::format("{}({})", s.attr(AttrId(v.index)).name, object_name(v.owner));
    case Variable::Kind::Atom: {
        const Atom& a = atoms[v.owner];
        std::string args;
        for (ObjectId t : a.homs) {
            args += (args.empty() ? "" : ", ") + object_name(t);
        }
        for (const auto& val : a.attrs) {
            args += (args.empty() ? "" : ", ") + (val == kUnknown ? "?" : val.to_string());
        }
        return fmt::format("{}({})", s.ob(a.ob).name, args);
    }
    }
    CATPLAN_UNREACHABLE("variable kind");
}

std::string Task::describe(Fact fact) const {
    const Variable& v = vars[fact.var];
    switch (v.kind) {
    case Variable::Kind::Presence:
    case Variable::Kind::Atom:
        return (fact.value == 1 ? "" : "not ") + describe(fact.var);
    case Variable::Kind::Hom:
        return fmt::format("{} = {}", describe(fact.var), object_name(v.targets[fact.value]));
    case Variable::Kind::Attr: {
        const Value& val = v.values[fact.value];
        return fmt::format("{} = {}", describe(fact.var), val == kUnknown ? "?" : val.to_string());
    }
    }
    CATPLAN_UNREACHABLE("variable kind");
}

std::string Task::describe_action(ActionId id) const {
    const Action& a = actions[id];
    return fmt::format("{}({})", problem->domain->rules[a.rule]->name,
                       fmt::join(argument_names(a), ", "));
}

std::vector<std::string> Task::argument_names(const Action& a) const {
    const Rule& rule = *problem->domain->rules[a.rule];
    std::vector<std::string> out;
    out.reserve(rule.parameters.size());
    for (const auto& p : rule.parameters) {
        Image c = a.match[p.ob.index()][p.part];
        out.push_back(c.atom ? describe(atoms[c.id].var) : object_name(c.id));
    }
    return out;
}

} // namespace catplan::plan::ground
