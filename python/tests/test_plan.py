"""Plans, validation and the planner; long searches release the GIL and stop on Ctrl-C."""

import os
import signal
import threading
import time

import pytest

import catplan


def test_the_paper_plan_is_valid(case_study, paper_plan):
    assert len(paper_plan) == 8 and str(paper_plan[0]) == "unstack(E, D)"
    v = catplan.validate(case_study["CaseStudy"], paper_plan, keep_states=True)
    assert v.valid and v.goal_reached and v.failed_step is None and v.reason == ""
    assert len(v.matches) == 8 and len(v.states) == 9
    first = v.matches[0]
    assert first("Block", "block") == v.states[0].find_part("Block", "E")
    assert first.bindings()["underblock"] == "D"
    assert v.final_state.nparts("Block") == v.states[-1].nparts("Block")


def test_an_invalid_plan_is_an_answer_with_a_reason(case_study):
    v = catplan.validate(case_study["CaseStudy"], ["pickup(E)"])
    assert not v and v.failed_step == 0
    assert v.reason.startswith("step 1 pickup(E): no match")


def test_a_plan_costs_what_its_rules_and_the_problems_values_say():
    here = os.path.dirname(os.path.abspath(__file__))
    m = catplan.load(os.path.join(here, "..", "..", "tests", "cli", "data", "roads.cp"))
    cheapest = ["drive(t1, a, b)", "drive(t1, b, c)", "drive(t1, c, d)"]
    assert catplan.validate(m["ToD"], cheapest).cost == 12
    assert catplan.validate(m["ToD"], ["drive(t1, a, d)"]).cost == 20
    through_e = catplan.validate(m["ToD"], ["drive(t1, a, e)", "drive(t1, e, d)"])
    assert not through_e and "its cost length(a, e) has no value" in through_e.reason
    assert catplan.validate(m["ToDInSteps"], ["drive(t1, a, d)"]).cost is None


def test_plans_from_text_steps_and_tuples():
    p = catplan.Plan(["unstack(E, D)", catplan.Step("putdown", ["E"]), ("pickup", ["B"])])
    assert [str(s) for s in p] == ["unstack(E, D)", "putdown(E)", "pickup(B)"]
    assert catplan.Plan.parse(str(p)) == p
    with pytest.raises(catplan.CatplanError) as info:
        catplan.Plan.parse("unstack(E,\n", filename="bad.plan")
    assert info.value.diagnostics[0].file == "bad.plan"


def two_blocks(case_study):
    """A and B on the table; the goal: A on B."""
    s = case_study["ColorBlocksworld"]
    initial = catplan.State.from_dict(s, {
        "Block": [{"_name": n, "hasColor": c, "isClear": True, "isOnTable": True}
                  for n, c in (("A", "red"), ("B", "green"))] + [{}],
        "Gripper": [{"_name": "gripper", "isHolding": 2}],
        "Empty": [{"_name": "empty", "isEmpty": 2}],
    })
    goal = catplan.State.from_dict(s, {
        "Block": [{"hasColor": "red"}, {"hasColor": "green"}],
        "On": [{"on_l": 0, "on_r": 1}],
    })
    return catplan.Problem(case_study["Blocksworld"], initial, goal, name="TwoBlocks")


def test_the_planner_finds_a_plan_that_validates(case_study):
    problem = two_blocks(case_study)
    r = catplan.plan(problem)
    assert r.solved and r.status == "solved"
    assert [str(s) for s in r.plan] == ["pickup(A)", "stack(A, B)"]
    assert r.stats["expanded"] > 0
    assert catplan.validate(problem, r.plan).valid
    astar = catplan.plan(problem, search="astar", heuristic="goalcount")
    assert len(astar.plan) == 2
    # Each heuristic's value on the initial state, as the first search saw it: of the goal,
    # only the On fact is missing (the colours hold); breadth-first search has none.
    assert astar.stats["initial_h"] == {"goalcount": 1}
    assert r.stats["initial_h"] == {}


def test_unknown_search_names_are_value_errors(case_study):
    with pytest.raises(ValueError, match="astar"):
        catplan.plan(case_study["CaseStudy"], search="dfs")


def big_problem(case_study, blocks=8):
    """Blocks on a table and a goal no state reaches: a search that runs for minutes."""
    m = case_study
    names = [chr(ord("A") + i) for i in range(blocks)]
    rows = [{"_name": n, "hasColor": "red", "isClear": True, "isOnTable": True} for n in names]
    rows.append({})  # the hand-empty marker block
    initial = catplan.State.from_dict(m["ColorBlocksworld"], {
        "Block": rows,
        "Gripper": [{"_name": "gripper", "isHolding": blocks}],
        "Empty": [{"_name": "empty", "isEmpty": blocks}],
    })
    goal = catplan.State.from_dict(m["ColorBlocksworld"], {"Block": [{"hasColor": "black"}]})
    return catplan.Problem(m["Blocksworld"], initial, goal, name="Unreachable")


def test_ctrl_c_interrupts_a_search(case_study):
    problem = big_problem(case_study)
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        catplan.plan(problem, max_time=120)
    timer.join()
    assert time.monotonic() - start < 30


def test_a_progress_callback_can_stop_a_search(case_study):
    calls = []

    def progress(stats):
        calls.append(stats)
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        catplan.plan(big_problem(case_study), max_time=120, progress=progress,
                     progress_interval=0.1)
    assert len(calls) == 1 and calls[0]["expanded"] > 0


def test_a_search_releases_the_gil(case_study):
    problem = big_problem(case_study)
    result = {}
    worker = threading.Thread(target=lambda: result.update(r=catplan.plan(problem,
                                                                          max_time=1.0)))
    worker.start()
    ticks = 0
    while worker.is_alive():
        time.sleep(0.001)
        ticks += 1
    worker.join()
    assert result["r"].status == "time limit"
    assert ticks > 50  # the main thread ran while the search did
