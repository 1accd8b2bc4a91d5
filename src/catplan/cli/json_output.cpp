#include "catplan/cli/json_output.hpp"

#include "catplan/base/assert.hpp"
#include "catplan/cli/common.hpp"
#include "catplan/json/json.hpp"
#include "catplan/plan/actions.hpp"

namespace catplan::cli {

nlohmann::ordered_json acset_value(const acset::ACSet& x) {
    return nlohmann::ordered_json::parse(json::write_acset(x, /*pretty=*/false, /*names=*/true));
}

nlohmann::ordered_json schema_value(const schema::Schema& s) {
    return nlohmann::ordered_json::parse(json::write_schema(s));
}

nlohmann::ordered_json morphism_json(const hom::ACSetMorphism& f, const acset::ACSet& x,
                                     const acset::ACSet& y) {
    const auto& s = x.schema();
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (std::uint32_t o = 0; o < s.num_obs(); ++o) {
        ObId ob(o);
        if (x.num_parts(ob) == 0) {
            continue;
        }
        nlohmann::ordered_json parts = nlohmann::ordered_json::object();
        for (Part p = 0; p < x.num_parts(ob); ++p) {
            parts[x.part_label(ob, p)] = y.part_label(ob, f.components[o][p]);
        }
        j[s.ob(ob).name] = std::move(parts);
    }
    for (std::uint32_t t = 0; t < s.num_attr_types(); ++t) {
        AttrTypeId ty(t);
        if (x.num_vars(ty) == 0) {
            continue;
        }
        nlohmann::ordered_json vars = nlohmann::ordered_json::object();
        for (std::uint32_t v = 0; v < x.num_vars(ty); ++v) {
            vars[x.value_label(ty, acset::Value::var(v))] =
                y.value_label(ty, f.var_components[t][v]);
        }
        j[s.attr_type(ty).name] = std::move(vars);
    }
    return j;
}

nlohmann::ordered_json step_json(const std::string& action,
                                 const std::vector<std::string>& arguments,
                                 nlohmann::ordered_json match) {
    nlohmann::ordered_json j = {{"action", action}, {"arguments", arguments}};
    if (!match.is_null()) {
        j["match"] = std::move(match);
    }
    return j;
}

nlohmann::ordered_json declaration_json(const lang::Declaration& d) {
    std::string kind(kind_name(d.kind));
    kind = kind.substr(kind.find(' ') + 1); // "a schema" -> "schema"
    return {{"kind", kind}, {"name", d.name}, {"summary", lang::summarize(d)}};
}

std::string json_text(const nlohmann::ordered_json& doc) {
    return json::dump(doc, 2) + "\n";
}

nlohmann::ordered_json validation_json(bool valid, bool goal_reached,
                                       std::optional<std::size_t> failed_step,
                                       const std::string& reason, const std::string& location,
                                       nlohmann::ordered_json steps) {
    nlohmann::ordered_json j = {{"valid", valid}, {"goal_reached", goal_reached}};
    j["steps"] = std::move(steps);
    j["failed_step"] = nullptr;
    if (failed_step) {
        j["failed_step"] = {{"index", *failed_step}, {"location", location}};
    }
    j["reason"] = valid ? "" : reason;
    return j;
}

nlohmann::ordered_json validated_steps_json(const plan::Problem& problem,
                                            const std::vector<plan::Step>& steps,
                                            const plan::Validation& v) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < v.matches.size() && i + 1 <= v.states.size(); ++i) {
        const auto* rule = problem.domain->find_rule(steps[i].action);
        CATPLAN_ASSERT(rule != nullptr, "a step that applied names a rule of the domain");
        plan::Step a = plan::action_step(*rule, steps[i]);
        auto step = step_json(a.action, a.args, morphism_json(v.matches[i], rule->L, v.states[i]));
        if (a.action != rule->name || a.args != steps[i].args) {
            step["rule"] = steps[i].to_string();
        }
        out.push_back(std::move(step));
    }
    return out;
}

} // namespace catplan::cli
