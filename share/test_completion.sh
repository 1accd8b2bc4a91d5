#!/bin/bash
# test_completion.sh catplan.bash: completing subcommands, options, option values and files,
# with the script alone and after bash-completion's own helpers are loaded.
set -eu
script=$1

complete_words() {
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    COMPREPLY=()
    _catplan
    echo "${COMPREPLY[*]-}"
}

expect() {
    local want=$1 got
    shift
    got=$(complete_words "$@")
    [[ " $got " == *" $want "* ]] || { echo "'$*': expected '$want' among '$got'" >&2; exit 1; }
}

expect_exactly() {
    local want=$1 got
    shift
    got=$(complete_words "$@")
    [[ $got == "$want" ]] || { echo "'$*': expected '$want', got '$got'" >&2; exit 1; }
}

checks() {
    expect_exactly "transfer" catplan tr
    expect_exactly "migrate migrate-domain" catplan mig
    expect_exactly "export import" catplan json ""
    expect_exactly "--pretty" catplan json export --pr
    expect_exactly "--rename-by-type --replan" catplan transfer x.cp --re
    expect_exactly "lama lazy gbfs astar bfs" catplan plan x.cp --search ""
    expect_exactly "gbfs" catplan transfer x.cp --replan --heuristic hff --search g
    expect_exactly "" catplan plan x.cp --max-time ""
    expect_exactly "" catplan transfer x.cp --map ""
    expect "--version" catplan --
    expect "world.cp" catplan check wo
    expect "world.cp" catplan transfer x.cp --plan wo
}

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
touch world.cp

(source "$script" && checks)
if [[ -f /usr/share/bash-completion/bash_completion ]]; then
    (source /usr/share/bash-completion/bash_completion && source "$script" &&
        declare -F _filedir >/dev/null && checks)
fi
echo "bash completion ok"
