// One blocksworld action on states of growing size: the cost of a rewrite must not grow with the
// state beyond the parts the rule touches (in-place application, indexed matching).
//
// Each iteration applies unstack(E, D) then stack(E, D), which restores the state up to part
// numbering, so the state size stays fixed. Each action is grounded from its two arguments (the
// match completed by search, as a plan step is) and applied with rewrite_in_place.

#include "catplan/rewrite/dpo.hpp"

#include <benchmark/benchmark.h>

namespace catplan {
namespace {

using acset::ACSet;
using acset::Value;
using hom::ACSetMorphism;
using rewrite::Rule;

struct Blocksworld {
    std::shared_ptr<schema::Schema> s = std::make_shared<schema::Schema>("ColorBlocksworld");
    ObId block = s->add_ob("Block");
    ObId empty = s->add_ob("Empty");
    ObId gripper = s->add_ob("Gripper");
    ObId on = s->add_ob("On");
    HomId on_l = s->add_hom("on_l", on, block);
    HomId on_r = s->add_hom("on_r", on, block);
    HomId is_empty = s->add_hom("isEmpty", empty, block);
    HomId is_holding = s->add_hom("isHolding", gripper, block);
    AttrTypeId color_t = s->add_attr_type("Color", schema::ValueKind::String);
    AttrTypeId clear_t = s->add_attr_type("Clear", schema::ValueKind::Bool);
    AttrTypeId table_t = s->add_attr_type("OnTable", schema::ValueKind::Bool);
    AttrId has_color = s->add_attr("hasColor", block, color_t);
    AttrId is_clear = s->add_attr("isClear", block, clear_t);
    AttrId is_on_table = s->add_attr("isOnTable", block, table_t);

    ACSetMorphism map(std::vector<std::vector<Part>> parts) const {
        ACSetMorphism f;
        f.components = std::move(parts);
        f.var_components.resize(3);
        return f;
    }

    // unstack(block, underblock): Pre has the hand empty (gripper and empty point at a marker
    // block) and block on underblock, block clear; Keep has the two blocks and the gripper with its
    // hom unset (redirected); Eff has the gripper holding block and underblock clear.
    Rule unstack() const {
        Rule r(s);
        r.L.add_parts(block, 3); // block, underblock, marker
        Part g = r.L.add_part(gripper);
        r.L.set_subpart(is_holding, g, 2);
        r.L.set_subpart(is_empty, r.L.add_part(empty), 2);
        Part o = r.L.add_part(on);
        r.L.set_subpart(on_l, o, 0);
        r.L.set_subpart(on_r, o, 1);
        r.L.set_subpart(is_clear, 0, Value::boolean(true));
        r.K.add_parts(block, 2);
        r.K.add_part(gripper);
        r.R = r.K;
        r.R.set_subpart(is_holding, 0, 0);
        r.R.set_subpart(is_clear, 1, Value::boolean(true));
        r.l = map({{0, 1}, {}, {0}, {}});
        r.r = map({{0, 1}, {}, {0}, {}});
        r.parameters = {{"block", block, 0}, {"underblock", block, 1}};
        return r;
    }

    // stack(block, underblock): the inverse of unstack.
    Rule stack() const {
        Rule r(s);
        r.L.add_parts(block, 2);
        r.L.set_subpart(is_holding, r.L.add_part(gripper), 0);
        r.L.set_subpart(is_clear, 1, Value::boolean(true));
        r.K.add_parts(block, 2);
        r.K.add_part(gripper);
        r.R = r.K;
        Part marker = r.R.add_part(block);
        r.R.set_subpart(is_holding, 0, marker);
        r.R.set_subpart(is_empty, r.R.add_part(empty), marker);
        Part o = r.R.add_part(on);
        r.R.set_subpart(on_l, o, 0);
        r.R.set_subpart(on_r, o, 1);
        r.R.set_subpart(is_clear, 1, Value::boolean(false));
        r.l = map({{0, 1}, {}, {0}, {}});
        r.r = map({{0, 1}, {}, {0}, {}});
        r.parameters = {{"block", block, 0}, {"underblock", block, 1}};
        return r;
    }

    // n blocks in towers of two (tops clear), the hand empty; returns the state.
    ACSet state(std::size_t n) const {
        ACSet x(s);
        x.reserve(block, n + 1);
        for (std::size_t i = 0; i < n; ++i) {
            Part b = x.add_part(block);
            x.set_subpart(has_color, b, Value::string(i % 2 ? "red" : "blue"));
            x.set_subpart(is_clear, b, Value::boolean(i % 2 == 1));
            x.set_subpart(is_on_table, b, Value::boolean(i % 2 == 0));
            if (i % 2 == 1) {
                Part o = x.add_part(on);
                x.set_subpart(on_l, o, b);
                x.set_subpart(on_r, o, b - 1);
            }
        }
        Part marker = x.add_part(block);
        x.set_subpart(is_holding, x.add_part(gripper), marker);
        x.set_subpart(is_empty, x.add_part(empty), marker);
        x.build_indexes();
        return x;
    }
};

// Finds the unique match of a rule with its two parameters bound.
ACSetMorphism ground(const Rule& rule, const ACSet& x, ObId block, Part top, Part below) {
    rewrite::MatchOptions opt;
    opt.initial = {{block, 0, top}, {block, 1, below}};
    opt.max_results = 1;
    auto matches = rewrite::find_matches(rule, x, opt);
    if (matches.empty()) {
        std::abort();
    }
    return matches[0];
}

// One iteration = two actions, each grounded from its two arguments and applied in place.
void BM_UnstackStack(benchmark::State& st) {
    Blocksworld bw;
    auto n = static_cast<std::size_t>(st.range(0));
    ACSet x = bw.state(n);
    Rule unstack = bw.unstack(), stack = bw.stack();
    Part top = 1, below = 0; // the first tower
    for (auto _ : st) {
        auto m1 = ground(unstack, x, bw.block, top, below);
        auto r1 = rewrite::rewrite_in_place(unstack, x, m1);
        top = (*r1)(bw.block, 0);
        below = (*r1)(bw.block, 1);
        auto m2 = ground(stack, x, bw.block, top, below);
        auto r2 = rewrite::rewrite_in_place(stack, x, m2);
        top = (*r2)(bw.block, 0);
        below = (*r2)(bw.block, 1);
        benchmark::DoNotOptimize(x);
    }
    st.counters["parts"] = static_cast<double>(x.total_parts());
    st.SetItemsProcessed(st.iterations() * 2);
}

// n blocks in towers of two give about 1.5 n parts: 66 -> 100 parts, 66666 -> 100,000 parts.
BENCHMARK(BM_UnstackStack)->Arg(66)->Arg(666)->Arg(6666)->Arg(66666);

} // namespace
} // namespace catplan

BENCHMARK_MAIN();
