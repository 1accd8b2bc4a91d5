"""States: parts, homs and attributes as Python values; dicts, tables, JSON and text."""

import copy

import pytest

import catplan


def test_parts_homs_and_attributes_are_python_values(case_study):
    x = case_study["Initial"]
    assert x.name == "Initial"
    assert x.nparts("Block") == 7
    assert x.part_names("Block")[:6] == ["A", "B", "C", "D", "E", "F"]
    assert x.subpart("hasColor", "A") == "green"
    assert x.subpart("isClear", "E") is True
    on = x.find_part("On", "x1")
    assert x.subpart("on_l", on) == x.find_part("Block", "E")
    assert x.incident("on_r", "D") == [on]
    held = x.subpart("isHolding", 0)
    assert x.label("Block", held) == "#7"
    colour = x.subpart("hasColor", held)
    assert isinstance(colour, catplan.Var) and colour.type == "Color"
    assert colour in x.variables("Color")


def test_to_dict_and_from_dict_round_trip(case_study):
    x = case_study["Initial"]
    d = x.to_dict()
    assert d["Block"][0] == {"_name": "A", "hasColor": "green", "isClear": True,
                             "isOnTable": True}
    assert d["On"][0]["on_l"] == 4  # E, 0-based
    assert len(d["Color"]) == x.nparts("Block") - 6  # the empty block's unknown colour
    y = catplan.State.from_dict(x.schema, d)
    assert y == x and y.part_names("Block") == x.part_names("Block")


def test_from_dict_resolves_names_and_rejects_bad_data(case_study):
    s = case_study["ColorBlocksworld"]
    y = catplan.State.from_dict(s, {
        "On": [{"on_l": "top", "on_r": "bottom"}],
        "Block": [{"_name": "top", "hasColor": "red"}, {"_name": "bottom"}],
    })
    assert y.subpart("on_l", 0) == 0 and y.subpart("on_r", 0) == 1
    assert y.subpart("isClear", "top") is None
    with pytest.raises(KeyError, match="Table"):
        catplan.State.from_dict(s, {"Table": []})
    with pytest.raises(KeyError, match="nobody"):
        catplan.State.from_dict(s, {"Block": [{}], "On": [{"on_l": "nobody"}]})
    with pytest.raises(TypeError, match="String"):
        catplan.State.from_dict(s, {"Block": [{"hasColor": 3}]})
    with pytest.raises(IndexError):
        catplan.State.from_dict(s, {"Block": [{}], "On": [{"on_l": 5}]})


def test_building_a_state_and_copy_on_write(case_study):
    m = case_study
    x = m["Initial"]
    x.add_part("Block", "G", hasColor="blue", isClear=True, isOnTable=True)
    assert x.nparts("Block") == 8
    assert m["Initial"].nparts("Block") == 7  # the module's state is unchanged
    y = copy.copy(x)
    y.set_subpart("hasColor", "G", "red")
    assert x.subpart("hasColor", "G") == "blue"
    v = y.add_var("Color", "c")
    y.set_subpart("hasColor", "G", v)
    assert y.subpart("hasColor", "G") == catplan.Var("Color", v.index)
    moved = y.remove_part("Block", "A")
    assert moved == 7 and y.part_names("Block")[0] == "G"
    with pytest.raises(IndexError):
        y.subpart("hasColor", 99)
    with pytest.raises(KeyError):
        y.subpart("colour", 0)


def test_json_round_trip(case_study):
    x = case_study["Initial"]
    text = x.to_json()
    y = catplan.State.from_json(x.schema, text)
    assert y == x
    schema = catplan.Schema.from_json(x.schema.to_json(), name="ColorBlocksworld")
    assert schema.obs == x.schema.obs


def test_bad_json_is_located():
    s = catplan.loads("@present G(FreeSchema) begin\n (V, E)::Ob\n (src, tgt)::Hom(E, V)\nend\n")
    with pytest.raises(catplan.CatplanError) as info:
        catplan.State.from_json(s["G"], '{"V": [{"_id": 1}],\n "E": [{"_id": 1, "src": 7}]}',
                                filename="g.json")
    d = info.value.diagnostics[0]
    assert d.file == "g.json" and d.line == 2


def test_tables_are_numpy_columns(case_study):
    np = pytest.importorskip("numpy", reason="numpy is optional (python3-numpy)")
    t = case_study["Initial"].to_tables()
    block = t["Block"]
    assert block["_name"][0] == "A"
    assert block["hasColor"].dtype == object  # the empty block's colour is unknown
    on = t["On"]
    assert on["on_l"].dtype == np.int64 and list(on["on_l"]) == [4, 3]
    assert set(t) == {"Block", "Empty", "Gripper", "On"}


def test_text_and_pictures(case_study):
    x = case_study["Initial"]
    assert "hasColor" in str(x)
    assert catplan.loads(case_study["ColorBlocksworld"].to_text() + x.to_text("Again"))[
        "Again"] == x
    assert x.to_dot().startswith("digraph")
    assert "Initial" in repr(x)


def test_tables_without_numpy_are_lists(case_study, monkeypatch):
    import sys
    monkeypatch.setitem(sys.modules, "numpy", None)  # import numpy now raises ImportError
    t = case_study["Initial"].to_tables()
    assert t["On"]["on_l"] == [4, 3]
    assert t["Block"]["hasColor"][0] == "green"
