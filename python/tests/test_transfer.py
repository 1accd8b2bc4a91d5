"""Plan transfer: the paper's case study, step by step, and its report."""

import catplan


def test_the_paper_plan_transfers(case_study, paper_plan):
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"], paper_plan,
                         keep_states=True)
    assert t.valid and t.reason == "" and t.source_valid
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


def test_a_failing_transfer_says_where(case_study):
    t = catplan.transfer(case_study["ColorToKitchen"], case_study["CaseStudy"],
                         ["unstack(E, D)", "putdown(E)"])
    assert not t.valid and t.failed_step is None
    assert t.reason.startswith("goal not reached")
    assert t.goal.satisfied < t.goal.total and t.goal.unsatisfied


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
