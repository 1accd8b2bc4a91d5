"""PDDL in and out, and IPC plans."""

import pytest

import catplan


@pytest.fixture(scope="module")
def blocks(source_dir):
    return catplan.load_pddl(str(source_dir / "tests/pddl/blocksworld-domain.pddl"),
                             str(source_dir / "tests/pddl/blocksworld-p01.pddl"))


def test_import_makes_a_domain_and_a_problem(blocks):
    assert isinstance(blocks.domain, catplan.Domain)
    assert "block" in blocks.schema.obs
    actions = dict(blocks.actions)
    assert "stack" in actions and actions["stack"][0] == "stack"
    assert blocks.problem.initial.nparts("block") == 5


def test_ipc_plans_validate_with_pddl_reasons(blocks, source_dir):
    good = (source_dir / "tests/pddl/blocksworld-p01.plan").read_text()
    assert blocks.validate(good).valid
    bad = (source_dir / "tests/pddl/blocksworld-p01-invalid.plan").read_text()
    v = blocks.validate(bad)
    assert not v.valid and "precondition" in v.reason and v.failed_step is not None
    steps = catplan.parse_ipc_plan(good)
    assert steps[0] == ("unstack", ["e", "d"])
    assert blocks.validate(steps).valid


def test_planning_and_writing_the_plan_back(blocks):
    r = catplan.plan(blocks.problem, search="astar", heuristic="hff", max_time=60)
    assert r.solved
    text = blocks.to_ipc(r.plan)
    assert text.rstrip().endswith("(unit cost)")
    assert blocks.validate(text).valid


def test_export_round_trips(blocks):
    domain = catplan.export_pddl(blocks.domain)
    problem = catplan.export_pddl_problem(blocks.problem)
    again = catplan.loads_pddl(domain, problem)
    assert [a for a, _ in again.actions] == [a for a, _ in blocks.actions]


def test_pddl_errors_are_located(source_dir):
    with pytest.raises(catplan.CatplanError) as info:
        catplan.load_pddl(str(source_dir / "tests/pddl/bad-parens.pddl"))
    d = info.value.diagnostics[0]
    assert d.file.endswith("bad-parens.pddl") and d.line is not None


def test_a_delta_domain_exports_as_pddl(source_dir):
    m = catplan.load(str(source_dir / "tests/pddl/lights.cp"))
    text = catplan.export_pddl(m["LightsProblem"].domain)
    assert "(define (domain LightsDomain)" in text and ":action" in text


def test_a_requirement_read_only_in_part_is_a_warning(source_dir):
    rooms = catplan.load_pddl(str(source_dir / "tests/pddl/adl-rooms-domain.pddl"),
                              str(source_dir / "tests/pddl/adl-rooms-p01.pddl"))
    [w] = rooms.warnings
    assert w.severity == "warning" and "':adl'" in w.message and w.line == 4
    assert rooms.validate("(light hall kitchen)\n(light kitchen study)\n").valid
    assert catplan.load_pddl(str(source_dir / "tests/pddl/blocksworld-domain.pddl")).warnings == []
