"""Ontology maps and data migration: Δ (the paper's Table 1), Σ, the generated actions."""

import os
import shutil
import subprocess

import pytest

import catplan


def test_the_map_in_brief(case_study):
    f = case_study["ColorToKitchen"]
    assert f.kind == "conjunctive" and not f.is_delta
    assert f.target.name == "KitchenWorld" and f.source.name == "ColorBlocksworld"
    lines = dict(f.describe())
    assert lines["Object"] == "Block"
    assert lines["BreadSliced"] == '{block::Block | hasColor(block) == "purple"}'
    assert "digraph" in f.to_dot()


def test_migrating_the_initial_state_gives_table_1(case_study):
    f = case_study["ColorToKitchen"]
    y = catplan.migrate(f, case_study["Initial"])
    assert y.schema == f.target
    assert y.part_names("BreadSliced") == ["D", "E"]
    assert y.part_names("TomatoSliced") == ["B"]
    assert y.nparts("Object") == 7 and y.nparts("InReceptacle") == 2
    assert y.subpart("breadSlicedHasTemperature", "D") == 0.0
    assert f.migrate(case_study["Initial"]) == y


def test_the_command_line_prints_the_same_tables(case_study, source_dir):
    # The ctest names the command just built; elsewhere, the one on PATH.
    binary = os.environ.get("CATPLAN_BINARY") or shutil.which("catplan")
    if not binary:
        pytest.skip("no catplan command: set CATPLAN_BINARY or put catplan on PATH")
    out = subprocess.run(
        [binary, "migrate", "examples/colorblocks_to_kitchen/appendix_map.cp", "--map",
         "ColorToKitchen", "Initial"], cwd=source_dir, capture_output=True, text=True,
        check=True).stdout
    y = catplan.migrate(case_study["ColorToKitchen"], case_study["Initial"])
    assert out.split("\n", 1)[1] == str(y)


def test_sigma_pushes_a_goal_back(source_dir):
    m = catplan.load(str(source_dir / "examples/colorblocks_to_blocks/forget_colors.cp"))
    x = catplan.sigma(m["ForgetColors"], m["PlainTower"])
    assert x.schema.name == "ColorBlocksworld"
    assert x.part_names("Block") == ["top", "middle", "bottom"]
    assert isinstance(x.subpart("hasColor", "top"), catplan.Var)
    assert x.subpart("isClear", "top") is True


def test_sigma_along_a_conjunctive_map_is_an_error(case_study):
    f = case_study["ColorToKitchen"]
    y = catplan.migrate(f, case_study["Initial"])
    with pytest.raises(catplan.CatplanError, match="delta"):
        catplan.sigma(f, y)


def test_migrated_domain_has_the_generated_actions(case_study):
    d = catplan.migrate_domain(case_study["ColorToKitchen"], case_study["Blocksworld"])
    assert [r.name for r in d.rules] == ["unstack", "stack", "pickup", "putdown"]
    assert d.schema.name == "KitchenWorld"
    with pytest.raises(ValueError):
        catplan.migrate_domain(case_study["ColorToKitchen"],
                               catplan.migrate_domain(case_study["ColorToKitchen"],
                                                      case_study["Blocksworld"]))


def test_a_state_on_the_wrong_schema_is_refused(case_study):
    f = case_study["ColorToKitchen"]
    with pytest.raises(ValueError):
        catplan.migrate(f, catplan.migrate(f, case_study["Initial"]))
