"""A transfer with PDDL inputs: an IPC plan in, the target domain's own actions out."""

import pytest

import catplan


@pytest.fixture(scope="module")
def blocks(source_dir):
    return catplan.load(str(source_dir / "examples/pddl/blocks/three_to_four.cp"))


@pytest.fixture(scope="module")
def warehouse(source_dir):
    return catplan.load(str(source_dir / "examples/pddl/warehouse/hospital_to_warehouse.cp"))


def test_moves_are_repaired_into_four_operator_steps(blocks, source_dir):
    d = source_dir / "examples/pddl/blocks"
    r = catplan.transfer_pddl(blocks, "ThreeToFour", str(d / "p01-3.pddl"),
                              (d / "p01-3.plan").read_text())
    assert r.valid and r.transfer.valid and r.pddl_valid
    assert [s.kind for s in r.steps] == ["repaired"] * 3
    assert r.steps[0].source == ("move-to-table", ["a", "b"])
    assert r.steps[0].target == [("unstack", ["a", "b"]), ("put-down", ["a"])]
    # Each move is its action's first: found from the migrated action's own sides.
    assert all(s.repair_from_action and s.repair_reused_from is None for s in r.steps)
    assert r.target_plan == [t for s in r.steps for t in s.target]
    assert len(r.target_plan) == 6
    assert r.plan_text.rstrip().endswith("; cost = 6 (unit cost)")
    assert "(:domain blocks4)" in r.problem_text
    assert r.source_cost is None and r.target_cost is None and r.comparison is None
    # The target plan is a plan of the 4-operator domain: catplan's own PDDL validator agrees.
    task = catplan.loads_pddl((d / "blocks4.pddl").read_text(), r.problem_text)
    assert task.validate(r.plan_text).valid


def test_delta_map_steps_correspond_and_the_users_problem_is_compared(warehouse, source_dir):
    d = source_dir / "examples/pddl/warehouse"
    plan = catplan.parse_ipc_plan((d / "warehouse-3.plan").read_text())
    r = catplan.transfer_pddl(warehouse, "HospitalToWarehouse", d / "warehouse-3.pddl", plan,
                              target_problem=d / "hospital-3.pddl")
    assert r.valid
    assert {s.kind for s in r.steps} == {"corresponds"}
    assert r.steps[0].action == "collect" and len(r.steps[0].target) == 1
    assert r.target_plan[0][0] == "collect"
    assert r.comparison["same"] and r.comparison["name"] == "hospital-3"
    assert r.transfer.verdict.goal.fraction == 1.0


def test_bad_plans_and_maps_raise_located_errors(blocks, source_dir):
    d = source_dir / "examples/pddl/blocks"
    with pytest.raises(catplan.CatplanError) as e:
        catplan.transfer_pddl(blocks, "ThreeToFour", str(d / "p01-3.pddl"), "(move a b)\n(fly a)\n")
    assert any(x.line == 2 for x in e.value.diagnostics)
    with pytest.raises(KeyError):
        catplan.transfer_pddl(blocks, "NoSuchMap", str(d / "p01-3.pddl"), "")
    with pytest.raises(catplan.CatplanError, match="cannot read"):
        catplan.transfer_pddl(blocks, "ThreeToFour", str(d / "missing.pddl"), "")


def test_an_invalid_source_plan_is_worded_as_validate_words_it(blocks, source_dir):
    d = source_dir / "examples/pddl/blocks"
    plan = "(move-to-table a b)\n(move e f d)\n"
    r = catplan.transfer_pddl(blocks, "ThreeToFour", str(d / "p02-3.pddl"), plan)
    assert not r.valid and not r.transfer.verdict.source_valid
    why = "step 2 (move e f d): precondition (clear e) does not hold"
    assert r.transfer.reason == "the source plan is invalid: " + why
    task = catplan.loads_pddl((d / "blocks3.pddl").read_text(), (d / "p02-3.pddl").read_text())
    assert task.validate(plan).reason == why


def test_the_functions_section_carries_the_costs(source_dir):
    d = source_dir / "tests/pddl"
    m = catplan.load(str(d / "roads_to_transit.cp"))
    plan = (d / "roads-p01.plan").read_text()
    r = catplan.transfer_pddl(m, "ToTransit", str(d / "roads-p01.pddl"), plan)
    assert r.valid and r.pddl_valid and (r.source_cost, r.target_cost) == (12, 12)
    assert r.uncarried_values == [] and "(= (travel-time a b) 3)" in r.problem_text
    # Without the section the travel times have no values: no cost, and the validator says no.
    w = catplan.transfer_pddl(m, "ToTransitWithoutTimes", str(d / "roads-p01.pddl"), plan)
    assert w.target_cost is None and w.pddl_valid is False
    # A fare is per bus and stop: no road length is one, and each left out is named.
    f = catplan.transfer_pddl(m, "ToFares", str(d / "roads-p01.pddl"), plan)
    assert f.target_cost is None and len(f.uncarried_values) == 5
    assert f.uncarried_values[0] == "(road-length a d)"


def test_repairs_sum_the_targets_costs(source_dir):
    d = source_dir / "tests/pddl"
    m = catplan.load(str(d / "roads_to_transit.cp"))
    plan = (d / "roads-p01.plan").read_text()
    r = catplan.transfer_pddl(m, "ToCharters", str(d / "roads-p01.pddl"), plan)
    # A departure and an arrival for the road's length, never a charter for 50.
    assert r.valid and r.pddl_valid and r.target_cost == 12
    assert [s.repair_cost for s in r.steps] == [3, 4, 5]
    assert all(s.repair_least_cost for s in r.steps)


def test_least_cost_repairs_are_reused_where_the_values_agree(source_dir):
    d = source_dir / "tests/pddl"
    m = catplan.load(str(d / "roads_to_transit.cp"))
    plan = (d / "roads-chain.plan").read_text()
    r = catplan.transfer_pddl(m, "ToCharters", str(d / "roads-chain.pddl"), plan)
    # The 60-long road takes the charter (50); the 2-long ones share a searched repair.
    assert r.valid and r.pddl_valid and (r.source_cost, r.target_cost) == (72, 62)
    assert [s.repair_cost for s in r.steps] == [2, 2, 2, 50, 2, 2, 2]
    assert all(s.repair_least_cost for s in r.steps)
    reused = [s.repair_reused_from for s in r.steps if s.repair_reused_from is not None]
    assert len(reused) >= 2 and r.steps[3].repair_reused_from is None
    assert all(r.steps[i].repair_cost == 2 for i in reused)
