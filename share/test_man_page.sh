#!/bin/sh
# test_man_page.sh catplan.1: the generated man page renders and documents every subcommand.
set -eu
page=$1
text=$(LC_ALL=C.UTF-8 MANWIDTH=100 man -l "$page" 2>&1)
fail() { echo "test_man_page.sh: $1" >&2; exit 1; }
echo "$text" | grep -q '^CATPLAN(1)' || fail "no CATPLAN(1) header"
for sub in check show homs "json export" "json import" dot validate plan migrate \
    migrate-domain transfer "pddl import" "pddl export" report; do
    echo "$text" | grep -q "^   catplan $sub\$" || fail "no section for 'catplan $sub'"
done
echo "$text" | grep -q -- '--rename-by-type  *name target parts after their type' ||
    fail "transfer's --rename-by-type is not described"
echo "$text" | grep -q -- '--search TEXT:{bfs,astar,gbfs}=bfs' || fail "plan's --search is missing"
echo "man page ok: $(echo "$text" | wc -l) lines"
