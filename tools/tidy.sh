#!/bin/sh
# clang-tidy (the checks of .clang-tidy) on the C++ files changed since the merge base with REV
# (default main), committed or not; `--all` checks every file of the build. A header counts through
# the .cpp and _test.cpp beside it. Any finding fails. Needs the dev build's compile_commands.json.
#   tools/tidy.sh [REV | --all]
set -eu
cd "$(dirname "$0")/.."
./tools/install-deps.sh tidy
DB=build/dev/compile_commands.json
[ -f "$DB" ] || cmake --preset dev >/dev/null
if [ "${1:-main}" = "--all" ]; then
    changed=$(python3 -c 'import json, sys; print("\n".join(e["file"] for e in json.load(open(sys.argv[1]))))' "$DB")
else
    rev=${1:-main}
    if ! git rev-parse --verify -q "$rev" >/dev/null; then
        echo "tidy: no '$rev' here; checking what the last commit changed"
        rev=HEAD~1
    fi
    base=$(git merge-base "$rev" HEAD)
    # On REV itself (a clean clone of main, as CI runs), what the last commit changed: for a
    # merge, what it brought in.
    if [ "$base" = "$(git rev-parse HEAD)" ] && git rev-parse -q --verify HEAD^1 >/dev/null; then
        base=HEAD^1
    fi
    changed=$({ git diff --name-only --diff-filter=d "$base" -- src tests bench
                git ls-files --others --exclude-standard -- src tests bench; } | grep -E '\.(cpp|hpp)$' || true)
fi
# The files to check: the changed sources, and for a changed header its .cpp and _test.cpp; only
# those the build compiles (the benchmarks are not in the dev build).
files=$(for f in $changed; do
    case "$f" in
    *.hpp) echo "${f%.hpp}.cpp"; echo "${f%.hpp}_test.cpp" ;;
    *) echo "$f" ;;
    esac
done | sort -u | python3 -c '
import json, os, sys
known = {os.path.realpath(e["file"]) for e in json.load(open(sys.argv[1]))}
for f in sys.stdin.read().split():
    if os.path.realpath(f) in known:
        print(f)' "$DB")
if [ -z "$files" ]; then
    echo "tidy: no changed source to check"
    exit 0
fi
echo "tidy: $(echo "$files" | wc -l) file(s)"
# clang 14 reports every defaulted operator<=> as a use of 0 for a null pointer, and under CI's
# -Werror that is an error; gcc checks -Wzero-as-null-pointer-constant on every build instead.
# shellcheck disable=SC2086
echo "$files" | xargs -P "${JOBS:-2}" -n 1 clang-tidy -p build/dev --quiet \
    --extra-arg=-Wno-zero-as-null-pointer-constant
echo "tidy: clean"
