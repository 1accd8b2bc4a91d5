#!/usr/bin/env python3
"""Fails when a file includes a catplan layer above its own, or another layer's detail/ folder.

The layers, lowest first (docs/architecture.md). A layer may include itself and any layer before it.
"""
import pathlib
import re
import sys

LAYERS = ["base", "schema", "acset", "hom", "colimit", "rewrite", "migrate", "plan", "transfer", "json", "dot", "lang", "pddl",
          "report", "cli"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"catplan/([a-z_]+)/([^"]+)"')


def main() -> int:
    # Optional argument: the src/catplan folder to check (the self-test points it at a fixture).
    default = pathlib.Path(__file__).resolve().parent.parent / "src" / "catplan"
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else default
    errors = []
    for path in sorted(root.rglob("*.[ch]pp")):
        layer = path.relative_to(root).parts[0]
        if layer not in LAYERS:
            errors.append(f"{path}: folder '{layer}' is not a known layer (add it to {__file__})")
            continue
        rank = LAYERS.index(layer)
        for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target, rest = m.group(1), m.group(2)
            if target not in LAYERS:
                errors.append(f"{path}:{lineno}: includes unknown layer '{target}'")
            elif LAYERS.index(target) > rank:
                errors.append(f"{path}:{lineno}: layer '{layer}' includes '{target}', which is above it")
            elif target != layer and rest.startswith("detail/"):
                errors.append(f"{path}:{lineno}: includes the private detail/ of layer '{target}'")
    for e in errors:
        print(e, file=sys.stderr)
    if errors:
        print(f"check_layers: {len(errors)} violation(s)", file=sys.stderr)
        return 1
    print(f"check_layers: ok ({len(LAYERS)} layers)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
