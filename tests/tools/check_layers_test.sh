#!/bin/sh
# The layer check must pass on the tree and fail on an upward include and on a detail/ include.
set -eu
ROOT=$1
python3 "$ROOT/tools/check_layers.py" >/dev/null
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$TMP/acset" "$TMP/hom/detail" "$TMP/lang"
printf '#include "catplan/hom/hom_search.hpp"\n' > "$TMP/acset/bad.cpp"
if python3 "$ROOT/tools/check_layers.py" "$TMP" 2>"$TMP/out"; then
    echo "upward include not caught"; exit 1
fi
grep -q "layer 'acset' includes 'hom', which is above it" "$TMP/out"
rm "$TMP/acset/bad.cpp"
printf '#include "catplan/hom/detail/search_state.hpp"\n' > "$TMP/lang/bad.cpp"
if python3 "$ROOT/tools/check_layers.py" "$TMP" 2>"$TMP/out"; then
    echo "detail include not caught"; exit 1
fi
grep -q "private detail/ of layer 'hom'" "$TMP/out"
echo "check_layers self-test: ok"
