#!/bin/sh
# The demo: the paper's case study. For now: the ColorBlocksworld schema and the initial state of
# the paper's Table 1, loaded from examples/ and printed as tables.
set -eu
CATPLAN=${1:-build/release/src/catplan/cli/catplan}
EX=examples/colorblocksworld/colorblocksworld.cp
echo "== catplan check $EX"
"$CATPLAN" check "$EX"
echo
echo "== catplan show $EX ColorBlocksworld"
"$CATPLAN" show "$EX" ColorBlocksworld
echo
echo "== catplan show $EX Initial   (the paper's Table 1, left column)"
"$CATPLAN" show "$EX" Initial
