"""Loading .cp files into modules, and errors as exceptions carrying located diagnostics."""

import pytest

import catplan


def test_module_gives_each_declaration_as_its_python_type(case_study):
    m = case_study
    assert isinstance(m["ColorBlocksworld"], catplan.Schema)
    assert isinstance(m["Initial"], catplan.State)
    assert isinstance(m["Blocksworld"], catplan.Domain)
    assert isinstance(m["CaseStudy"], catplan.Problem)
    assert isinstance(m["ColorToKitchen"], catplan.Map)
    assert m.kind("Initial") == "state"
    assert "ColorToKitchen" in m.own_names and "Initial" not in m.own_names
    assert list(m)[0] == m.names[0]
    assert set(m.maps) == {"ColorToKitchen"}
    assert m.get("Nothing") is None
    with pytest.raises(KeyError):
        m["Nothing"]


def test_summary_is_the_check_line(case_study):
    assert case_study.summary("Blocksworld") == (
        "domain Blocksworld (ColorBlocksworld): 4 rules: unstack, stack, pickup, putdown")


def test_schema_lists_its_generators(case_study):
    s = case_study["ColorBlocksworld"]
    assert s.name == "ColorBlocksworld"
    assert s.obs == ["Block", "Empty", "Gripper", "On"]
    assert ("on_l", "On", "Block") in s.homs
    assert ("hasColor", "Block", "Color") in s.attrs
    assert dict(s.attr_types)["Color"] == "String"
    assert s.kind("on_l") == "Hom" and "Block" in s and "Nope" not in s
    again = catplan.loads(s.to_text())["ColorBlocksworld"]
    assert again.obs == s.obs and again.homs == s.homs and again.attrs == s.attrs
    assert s == case_study["Initial"].schema and s != again


def test_errors_raise_with_every_located_diagnostic():
    text = ("@present G(FreeSchema) begin\n"
            "  V::Ob\n"
            "  src::Hom(E, V)\n"
            "  tgt::Hom(V, W)\n"
            "end\n")
    with pytest.raises(catplan.CatplanError) as info:
        catplan.loads(text, name="bad.cp")
    ds = info.value.diagnostics
    assert len(ds) >= 2
    assert all(d.file == "bad.cp" and d.severity == "error" for d in ds)
    assert [d.line for d in ds[:2]] == [3, 4]
    assert ds[0].column == 12 and "E" in ds[0].message
    assert "bad.cp:3:12: error:" in str(info.value)
    assert "^" in ds[0].rendered


def test_a_missing_file_is_an_error_without_a_location(tmp_path):
    with pytest.raises(catplan.CatplanError) as info:
        catplan.load(str(tmp_path / "missing.cp"))
    assert "missing.cp" in str(info.value)


def test_rules_show_their_three_states_and_maps(case_study):
    unstack = case_study["Blocksworld"].rule("unstack")
    assert unstack.name == "unstack"
    assert [p for p, _ in unstack.parameters][:2] == ["block", "underblock"]
    assert unstack.pre.nparts("Block") == 3  # block, underblock and the empty marker
    assert unstack.keep.nparts("Block") == 2
    assert unstack.l.is_monic()
    assert unstack.l.naturality_failures() == []
    assert "digraph" in unstack.to_dot()
    assert str(unstack).startswith("rule unstack(block, underblock)")
