#pragma once
// One ground task (compile.hpp) searched again and again, from other initial states to other
// goals, without grounding the domain again: a plan repair searches from each target state of a
// transfer to the migrated source state after each step (transfer/repair.hpp).
//
// The task is compiled once from a first problem; its objects, atoms, variables and ground actions
// stay. A later state is written in the task's variables:
//   - an entity is the part of the same name (or, in an object whose parts are all entities, the
//     part of the same number when the object has as many parts and no names);
//   - the other parts of an object that homs point into take its slots in order;
//   - a part of an object nothing points into is the atom with its hom values and attribute
//     values;
//   - every value must be one the task knows: a static value as compiled, a variable's value in
//     its domain (what relaxed reachability reached from the first state), an atom interned.
// A state reached from the first one by the domain's rules always can be written so; another
// (more parts than slots, a fact never reached) cannot, and the answer says why, so that the
// caller compiles its own problem instead. Then the search runs as ground_search.hpp's does, and
// its plan is replayed as DPO steps on the new state and validated against the new goal.
//
// The goal is written by names: each of its parts of an object that homs point into is the
// task's object of the same name, so the goal is one term of facts (hom and attribute values,
// atoms present). This is the goal of a repair (Δ_F(X_i), named as the target state is). A goal
// that is not named so cannot be written; a fact of it that the task never reaches makes it
// unreachable, and the search then says "unsolvable" for the goal *by names* (another monic
// morphism of the goal into a reachable state is not looked for).

#include "catplan/base/result.hpp"
#include "catplan/plan/ground/compile.hpp"
#include "catplan/plan/search.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace catplan::plan::ground {

class ReusableTask {
public:
    /// The task of problem, compiled once (within the options' limits), or why the grounded
    /// search does not apply to it.
    static Result<ReusableTask> compile(const ProblemPtr& problem, const SearchOptions& options,
                                        const CompileOptions& compile_options = {});

    /// The grounded search from `initial` to a state that holds `goal` by names (both on the
    /// problem's schema), or why they cannot be written in the task's terms. The result's plan
    /// names the parts of `initial`.
    Result<SearchResult> search(std::shared_ptr<const ACSet> initial,
                                std::shared_ptr<const ACSet> goal, const SearchOptions& options);

    /// The task as compiled (its initial state and goal are those of the last search).
    const Task& task() const { return *task_; }

    /// Seconds spent compiling.
    double compile_seconds() const { return compile_seconds_; }

private:
    ReusableTask() = default;

    std::optional<std::string> write_initial(const ACSet& x);
    std::optional<std::string> write_goal(const ACSet& g, bool& unreachable);
    std::optional<std::string> place_parts(const ACSet& x, std::vector<ObjectId>& object_of,
                                           ObId ob) const;
    std::optional<std::string> write_cells(const ACSet& x, ObId ob, Part p, ObjectId o,
                                           const std::vector<std::vector<ObjectId>>& object_of,
                                           std::vector<std::uint32_t>& values) const;
    std::optional<std::string> write_atoms(const ACSet& x, ObId ob,
                                           const std::vector<std::vector<ObjectId>>& object_of,
                                           std::vector<std::uint32_t>& values) const;
    std::optional<std::string> goal_object(const ACSet& g, ObId ob, Part p, ObjectId& o) const;
    void goal_fact(VarId var, std::uint32_t value, bool& unreachable);
    AtomId find_atom(const Atom& a) const;

    std::unique_ptr<Task> task_; // stable: the engines keep references to it during a search
    /// Per object of the schema, per name: the entity of that name.
    std::vector<std::unordered_map<std::string_view, ObjectId>> by_name_;
    /// Per object: the name of the part it was in the first state (empty for a slot).
    std::vector<std::string_view> names_;
    /// Per object of the schema: whether its parts are atoms.
    std::vector<char> atom_ob_;
    std::unordered_map<std::uint64_t, std::vector<AtomId>> atom_index_;
    std::map<VarId, std::uint32_t> goal_facts_; // while writing a goal
    double compile_seconds_ = 0;
};

} // namespace catplan::plan::ground
