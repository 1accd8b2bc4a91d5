"""Homomorphism search between states."""

import pytest

import catplan


def test_counts_agree_with_the_command_line(graphs):
    c3, bowtie = graphs["Cycle3"], graphs["Bowtie"]
    assert catplan.count_homs(c3, bowtie) == 7
    assert len(catplan.homs(c3, bowtie)) == 7
    assert catplan.count_homs(c3, c3, iso=True) == 3
    assert catplan.hom(c3, graphs["Path2"]) is None
    assert len(catplan.homs(c3, bowtie, max=2)) == 2


def test_monic_homs_and_initial_bindings(graphs):
    c3, bowtie = graphs["Cycle3"], graphs["Bowtie"]
    monic = catplan.homs(c3, bowtie, monic=True)
    assert monic and all(f.is_monic() for f in monic)
    fixed = catplan.homs(c3, bowtie, monic=True, initial={"V": {"a": "v4"}})
    assert len(fixed) == 1
    f = fixed[0]
    assert f("V", "a") == bowtie.find_part("V", "v4")
    assert f.bindings()["b"] == "v5"
    assert f.components["V"] == [3, 4, 0]
    assert f.naturality_failures() == []
    assert "digraph" in f.to_dot()


def test_isomorphism(graphs):
    c3 = graphs["Cycle3"]
    assert catplan.is_isomorphic(c3, c3.copy())
    assert not c3.is_isomorphic(graphs["Bowtie"])


def test_states_on_different_schemas_are_refused(graphs, case_study):
    with pytest.raises(ValueError, match="different schemas"):
        catplan.homs(graphs["Cycle3"], case_study["Initial"])
