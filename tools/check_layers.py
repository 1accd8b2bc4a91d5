#!/usr/bin/env python3
"""Fails on any include between catplan layers that the layer graph of docs/architecture.md does
not draw, and on an include of another layer's detail/ folder.

It also fails when a layer's CMakeLists.txt links a catplan library the graph does not let it build
on, or when src/catplan/CMakeLists.txt adds a layer before one it builds on.

The graph is the fenced ```layers block of docs/architecture.md, one line per layer:

    transfer -> migrate plan

says that transfer builds on migrate and plan: a file of transfer may include transfer itself and
every layer reachable from it along the drawn edges (migrate, plan and what they build on). A line
`base ->` declares a layer that builds on nothing. The graph must name every folder of
src/catplan, name no layer twice, and have no cycle.

Usage: check_layers.py [SRC_CATPLAN_DIR [ARCHITECTURE_MD]] (the self-test points both at
fixtures; by default the repository's own).
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"catplan/([a-z_]+)/([^"]+)"')
BLOCK = re.compile(r"^```layers\s*\n(.*?)^```", re.M | re.S)
LINE = re.compile(r"^([a-z_]+)\s*->\s*((?:[a-z_]+\s*)*)$")
LINK = re.compile(r"\bcatplan::([a-z_]+)\b")
ORDER = re.compile(r"^foreach\(layer ([a-z_ ]+)\)", re.M)


def read_graph(doc: pathlib.Path):
    """The drawn edges {layer: [layers it builds on]} in the document's order, or errors."""
    text = doc.read_text(encoding="utf-8")
    blocks = BLOCK.findall(text)
    if len(blocks) != 1:
        return None, [f"{doc}: expected one ```layers block, found {len(blocks)}"]
    graph, errors = {}, []
    first = text[: text.index(blocks[0])].count("\n") + 1
    for offset, line in enumerate(blocks[0].splitlines()):
        line = line.split("#", 1)[0].strip()
        where = f"{doc}:{first + offset}"
        if not line:
            continue
        m = LINE.match(line)
        if not m:
            errors.append(f"{where}: cannot read '{line}' (write: layer -> lower layers)")
        elif m.group(1) in graph:
            errors.append(f"{where}: layer '{m.group(1)}' is drawn twice")
        else:
            graph[m.group(1)] = m.group(2).split()
    for layer, below in graph.items():
        for b in below:
            if b not in graph:
                errors.append(f"{doc}: layer '{layer}' builds on '{b}', which is not drawn")
    return graph, errors


def reachable(graph):
    """For each layer, itself and every layer reachable from it; a cycle is an error."""
    closure, errors, state = {}, [], {}

    def visit(layer, path):
        if state.get(layer) == "open":
            errors.append("the layer graph has a cycle: " + " -> ".join(path + [layer]))
            return set()
        if layer not in closure:
            state[layer] = "open"
            seen = {layer}
            for b in graph.get(layer, []):
                seen |= visit(b, path + [layer])
            state[layer] = "done"
            closure[layer] = seen
        return closure[layer]

    for layer in graph:
        visit(layer, [])
    return closure, errors


def check_includes(root: pathlib.Path, closure, doc):
    errors = []
    for path in sorted(root.rglob("*.[ch]pp")):
        layer = path.relative_to(root).parts[0]
        if layer not in closure:
            errors.append(f"{path}: folder '{layer}' is not a layer of the graph in {doc}")
            continue
        for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target, rest = m.group(1), m.group(2)
            if target not in closure:
                errors.append(f"{path}:{lineno}: includes unknown layer '{target}'")
            elif target not in closure[layer]:
                errors.append(f"{path}:{lineno}: layer '{layer}' includes '{target}', which the "
                              f"layer graph does not let it build on")
            elif target != layer and rest.startswith("detail/"):
                errors.append(f"{path}:{lineno}: includes the private detail/ of layer '{target}'")
    return errors


def check_cmake(root: pathlib.Path, graph, closure):
    """The libraries each layer's CMakeLists.txt links (every catplan::NAME it names) must be
    layers it builds on, and the order src/catplan/CMakeLists.txt adds layers in must put each
    after the layers it builds on. Both files are optional (fixtures have none)."""
    errors = []
    for cmake in sorted(root.glob("*/CMakeLists.txt")):
        layer = cmake.parent.name
        if layer not in closure:
            continue  # reported with its sources
        for lineno, line in enumerate(cmake.read_text(encoding="utf-8").splitlines(), 1):
            for target in LINK.findall(line.split("#", 1)[0]):
                if target not in closure[layer]:
                    errors.append(f"{cmake}:{lineno}: layer '{layer}' links catplan::{target}, "
                                  f"which the layer graph does not let it build on")
    top = root / "CMakeLists.txt"
    order = ORDER.search(top.read_text(encoding="utf-8")) if top.exists() else None
    if order:
        listed = order.group(1).split()
        for i, layer in enumerate(listed):
            for b in graph.get(layer, []):
                if b in listed[i + 1:]:
                    errors.append(f"{top}: adds layer '{layer}' before '{b}', which it builds on")
    return errors


def main() -> int:
    repo = pathlib.Path(__file__).resolve().parent.parent
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else repo / "src" / "catplan"
    doc = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else repo / "docs" / "architecture.md"
    graph, errors = read_graph(doc)
    if graph is not None and not errors:
        closure, errors = reachable(graph)
        if not errors:
            errors = check_includes(root, closure, doc) + check_cmake(root, graph, closure)
    for e in errors:
        print(e, file=sys.stderr)
    if errors:
        print(f"check_layers: {len(errors)} violation(s)", file=sys.stderr)
        return 1
    edges = sum(len(b) for b in graph.values())
    print(f"check_layers: ok ({len(graph)} layers, {edges} drawn edges)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
