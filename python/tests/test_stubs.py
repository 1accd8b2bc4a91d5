"""The type stubs name exactly what the extension module has, and everything is documented."""

import ast
import inspect
from pathlib import Path

import catplan
from catplan import _catplan

STUB = Path(catplan.__file__).with_name("_catplan.pyi")


def stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            names = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    names.add(item.name)
                elif isinstance(item, ast.AnnAssign):
                    names.add(item.target.id)
            members[node.name] = {n for n in names if not n.startswith("_")}
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
    return top, members


def runtime_members(cls):
    own = set()
    for klass in cls.__mro__:
        if klass in (object, BaseException, Exception) or klass.__module__ == "pybind11_builtins":
            continue
        own |= {n for n in vars(klass) if not n.startswith("_")}
    return own


def test_stub_and_module_agree():
    top, members = stub_names()
    public = {n for n in dir(_catplan) if not n.startswith("_")}
    assert top == public
    for name, names in members.items():
        cls = getattr(_catplan, name)
        # An exception's diagnostics are set on each instance when it is raised.
        extra = {"diagnostics"} if name == "CatplanError" else set()
        assert names == runtime_members(cls) | extra, name


def test_everything_public_has_a_docstring():
    for name in dir(_catplan):
        if name.startswith("_"):
            continue
        obj = getattr(_catplan, name)
        doc = inspect.getdoc(obj) or ""
        if inspect.isclass(obj):
            assert len(doc) > 20, name
        else:
            # pybind11 starts a function's doc with its signature; the text must follow.
            assert len(doc.split("\n", 1)[-1].strip()) > 20, name
