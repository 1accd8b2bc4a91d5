#!/bin/sh
# Renders every golden .dot file of a folder to SVG; fails on any error or warning.
# Usage: render_all.sh DOT_EXECUTABLE FOLDER. Exits 77 (skipped) when DOT_EXECUTABLE is missing.
set -u
DOT=$1
DIR=$2
if [ ! -x "$DOT" ]; then
    echo "Graphviz dot not found: skipped"
    exit 77
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
status=0
count=0
for f in "$DIR"/*.dot; do
    count=$((count + 1))
    if ! "$DOT" -Tsvg "$f" -o "$TMP/out.svg" 2>"$TMP/err" || [ -s "$TMP/err" ]; then
        echo "$f does not render cleanly:"
        cat "$TMP/err"
        status=1
    fi
done
if [ "$count" -eq 0 ]; then
    echo "no .dot files in $DIR"
    exit 1
fi
echo "rendered $count DOT files"
exit $status
