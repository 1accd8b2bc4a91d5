#!/bin/sh
# The layer check must pass on the tree and, on fixtures with a graph of their own, catch an
# include the graph does not draw (upward, or sideways between siblings), an include of another
# layer's detail/, a folder the graph does not name, a link the graph does not allow, a build order
# against the graph, and a graph that is malformed or has a cycle; an include the graph reaches
# through a path is allowed.
set -eu
ROOT=$1
CHECK="python3 $ROOT/tools/check_layers.py"
$CHECK >/dev/null
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
DOC="$TMP/architecture.md"
SRC="$TMP/src"

# graph LINE...: writes a document whose layers block holds the lines.
graph() {
    { printf '# Architecture\n\n```layers\n'; printf '%s\n' "$@"; printf '```\n'; } > "$DOC"
}

# fails WHAT PATTERN: the check must fail on the fixture and say PATTERN.
fails() {
    if $CHECK "$SRC" "$DOC" 2>"$TMP/out" >/dev/null; then
        echo "not caught: $1"; exit 1
    fi
    if ! grep -q -- "$2" "$TMP/out"; then
        echo "$1: expected '$2' in:"; cat "$TMP/out"; exit 1
    fi
}

# passes WHAT: the check must pass on the fixture.
passes() {
    if ! $CHECK "$SRC" "$DOC" >/dev/null 2>"$TMP/out"; then
        echo "wrongly rejected: $1"; cat "$TMP/out"; exit 1
    fi
}

reset() {
    rm -rf "$SRC"
    mkdir -p "$SRC/base" "$SRC/acset" "$SRC/hom/detail" "$SRC/migrate" "$SRC/dot" \
        "$SRC/transfer" "$SRC/cli"
    for l in base acset hom migrate dot transfer cli; do : > "$SRC/$l/$l.cpp"; done
    graph 'base ->' 'acset -> base' 'hom -> acset' 'migrate -> hom' 'dot -> migrate' \
        'transfer -> migrate' 'cli -> dot transfer'
}

reset
passes "a fixture with no includes"

printf '#include "catplan/base/x.hpp"\n#include "catplan/hom/y.hpp"\n' > "$SRC/cli/a.cpp"
passes "an include reached through a path of edges"

reset
printf '#include "catplan/hom/hom_search.hpp"\n' > "$SRC/acset/bad.cpp"
fails "upward include" "layer 'acset' includes 'hom', which the layer graph does not let it"

reset
printf '#include "catplan/transfer/transfer.hpp"\n' > "$SRC/dot/bad.cpp"
fails "sideways include between siblings" "layer 'dot' includes 'transfer'"

reset
printf '#include "catplan/hom/detail/search_state.hpp"\n' > "$SRC/migrate/bad.cpp"
fails "detail include" "private detail/ of layer 'hom'"

reset
printf '#include "catplan/nowhere/x.hpp"\n' > "$SRC/cli/bad.cpp"
fails "unknown layer" "includes unknown layer 'nowhere'"

reset
mkdir "$SRC/db" && : > "$SRC/db/store.cpp"
fails "a folder the graph does not name" "folder 'db' is not a layer of the graph"

reset
printf 'catplan_add_layer(dot SOURCES dot.cpp DEPENDS catplan::transfer)\n' > "$SRC/dot/CMakeLists.txt"
fails "a link the graph does not allow" "layer 'dot' links catplan::transfer"

reset
printf 'foreach(layer base acset migrate hom dot transfer)\n' > "$SRC/CMakeLists.txt"
fails "a build order against the graph" "adds layer 'migrate' before 'hom'"

reset
graph 'base ->' 'acset -> base hom' 'hom -> acset' 'migrate -> hom' 'dot -> migrate' \
    'transfer -> migrate' 'cli -> dot transfer'
fails "a cycle" "the layer graph has a cycle"

reset
graph 'base ->' 'acset -> base' 'hom -> acset' 'migrate -> hom' 'dot -> migrate graph' \
    'transfer -> migrate' 'cli -> dot transfer'
fails "an edge to an undrawn layer" "layer 'dot' builds on 'graph', which is not drawn"

reset
graph 'base ->' 'acset -> base' 'acset -> base' 'hom -> acset' 'migrate -> hom' \
    'dot -> migrate' 'transfer -> migrate' 'cli -> dot transfer'
fails "a layer drawn twice" "layer 'acset' is drawn twice"

reset
graph 'base ->' 'acset <- base'
fails "a line that is no edge" "cannot read 'acset <- base'"

reset
printf '# Architecture\n\nno graph here\n' > "$DOC"
fails "a document without a graph" "expected one \`\`\`layers block, found 0"

echo "check_layers self-test: ok"
