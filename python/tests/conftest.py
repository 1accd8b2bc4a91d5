"""Shared fixtures: the repository's examples, loaded once per test session."""

import os
from pathlib import Path

import pytest

import catplan

SOURCE = Path(os.environ.get("CATPLAN_SOURCE_DIR", Path(__file__).resolve().parents[2]))
CASE_STUDY = SOURCE / "examples/colorblocks_to_kitchen/appendix_map.cp"
PAPER_PLAN = SOURCE / "examples/colorblocksworld/paper.plan"


@pytest.fixture(scope="session")
def source_dir() -> Path:
    return SOURCE


@pytest.fixture(scope="session")
def case_study() -> catplan.Module:
    return catplan.load(str(CASE_STUDY))


@pytest.fixture(scope="session")
def paper_plan() -> catplan.Plan:
    return catplan.Plan.load(str(PAPER_PLAN))


@pytest.fixture(scope="session")
def graphs() -> catplan.Module:
    return catplan.load(str(SOURCE / "tests/cli/data/graphs.cp"))
