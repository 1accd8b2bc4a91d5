"""Plan transfer: the paper's case study, step by step, its verdict and its report."""

import pytest

import catplan


def test_the_paper_plan_transfers(case_study, paper_plan):
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"], paper_plan,
                         keep_states=True)
    assert t.valid and t.reason == "" and t.verdict.source_valid
    assert t.verdict.status == "valid" and t.verdict.faults == [] and t.verdict.goal_name == ""
    assert t.migration == "conjunctive"
    assert [str(s.target) for s in t.steps] == [str(s) for s in paper_plan]
    first = t.steps[0]
    assert first.action == "unstack" and first.arguments == ["E", "D"]
    assert first.source_match.codom.schema.name == "ColorBlocksworld"
    assert first.target_match.codom.schema.name == "KitchenWorld"
    assert first.target_match.bindings()["block"] == "E"
    assert first.source_match.is_monic() and first.target_match.is_monic()
    assert (t.goal.satisfied, t.goal.total, t.goal.unsatisfied) == (52, 52, [])
    assert t.goal.fraction == 1.0
    assert len(t.target_states) == 9 and t.final_state.schema.name == "KitchenWorld"
    assert set(t.timings) == {"migrate_ms", "apply_ms", "validate_ms", "total_ms"}
    assert t.timings["total_ms"] >= t.timings["apply_ms"] >= 0


def test_renamed_by_type(case_study, paper_plan):
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"], paper_plan,
                         rename_by_type=True)
    assert str(t.steps[0].target) == "unstack(bread2, bread1)"


def test_a_transfer_that_misses_the_goal_says_why(case_study):
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"],
                         ["unstack(E, D)", "putdown(E)"])
    v = t.verdict
    assert not t.valid and not v and v.failed_step is None
    kinds = [f.kind for f in v.faults]
    assert kinds[0] == "goal" and "source_plan" in kinds  # the source plan misses it too
    assert t.reason == v.reason and v.reason.startswith("goal not reached")
    assert t.goal.satisfied < t.goal.total and t.goal.unsatisfied


def test_a_step_that_does_not_apply_is_the_reason(case_study):
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"],
                         ["unstack(E, D)", "pickup(E)"])
    f = t.verdict.failed_step
    assert f is not None and f.step == 1 and f.where == "step 2 pickup(E)"
    assert str(f).startswith("step 2 pickup(E): ")
    assert len(t.steps) == 1


def test_claims_name_their_hypotheses(case_study, source_dir, paper_plan):
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"], paper_plan)
    c = t.verdict.claim("valid_by_construction")
    assert not c.holds and c.failing is not None and not c.failing.holds
    assert any("delta" in h.statement for h in c.hypotheses)
    forget = catplan.load(str(source_dir / "examples/colorblocks_to_blocks/forget_colors.cp"))
    d = catplan.transfer(forget["ForgetColors"], forget["CaseStudy"], paper_plan).verdict
    delta = d.claim("valid_by_construction")
    assert d.valid and delta.holds and delta.failing is None
    assert [h.statement for h in delta.hypotheses] == [h.statement for h in c.hypotheses]
    with pytest.raises(KeyError):
        d.claim("optimal")


def test_an_intended_goal_judges_the_transfer(source_dir, paper_plan):
    m = catplan.load(str(source_dir / "examples/colorblocks_to_kitchen/swapped_map.cp"))
    t = catplan.transfer(m["SwappedToKitchen"], m["CaseStudy"], paper_plan, goal=m["Sandwich"])
    v = t.verdict
    assert not v.valid and v.goal_name == "Sandwich"
    assert v.reason == "the intended goal Sandwich is not satisfied"
    assert (v.goal.satisfied, v.goal.total) == (33, 37)
    assert "inReceptacle_r(i1) == plateIsReceptacle(plate)" in v.goal.unsatisfied
    assert [f.kind for f in v.faults] == ["intended_goal"]
    with pytest.raises(ValueError, match="target schema"):
        catplan.transfer(m["SwappedToKitchen"], m["CaseStudy"], paper_plan, goal=m["Initial"])


def test_replanning_and_the_report(case_study, paper_plan):
    # Replanning to the end takes seconds; a node limit keeps the test short.
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"], paper_plan,
                         keep_states=True, replan=True, search="gbfs", heuristic="hff",
                         max_nodes=5)
    assert t.replan.status == "node limit" and t.replan.stats["expanded"] == 5
    assert t.replan.steps == []
    html = t.report(no_timing=True)
    assert html.startswith("<!DOCTYPE html>") and "ColorToKitchen" in html
    assert "<svg" in html


def test_costs_are_carried_by_name(source_dir):
    m = catplan.load(str(source_dir / "tests/cli/data/roads_to_transit.cp"))
    cheapest = ["drive(t1, a, b)", "drive(t1, b, c)", "drive(t1, c, d)"]
    t = catplan.transfer(m["TransitToRoads"], m["ToD"], cheapest)
    assert t.valid and (t.source_cost, t.target_cost) == (12, 12)
    # Replanning with A* sums the same costs: the fewest drives (a to d, 20) are not the cheapest.
    astar = catplan.transfer(m["TransitToRoads"], m["ToD"], cheapest, replan=True, search="astar")
    assert astar.replan.cost == 12 and len(astar.replan.steps) == 3
    # The map forgets the cities that the cost reads: the target plan has no cost.
    lost = catplan.transfer(m["BusesToRoads"], m["ToD"], cheapest)
    assert lost.valid and (lost.source_cost, lost.target_cost) == (12, None)
    # Measured by steps, neither plan has a cost.
    steps = catplan.transfer(m["TransitToRoads"], m["ToDInSteps"], cheapest)
    assert (steps.source_cost, steps.target_cost) == (None, None)
