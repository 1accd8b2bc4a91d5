#!/bin/sh
# Installs the Debian packages catplan needs to build, test and run its demo, if any is missing.
# Runs apt-get as root, or through sudo for a user who is not root.
#   tools/install-deps.sh         what `make test`, `make demo` and `make bench` need
#   tools/install-deps.sh fuzz    that and clang with libFuzzer, for the fuzz preset (docs/fuzzing.md)
#   tools/install-deps.sh tidy    that and clang-tidy (tools/tidy.sh)
#   tools/install-deps.sh coverage that and gcovr (tools/coverage.sh)
set -eu

# lld links the release command, its functions in the order of cmake/catplan.order.
PACKAGES="g++ cmake ninja-build make python3 pkg-config clang-format lld
libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev libfmt-dev
libsqlite3-dev libicu-dev graphviz libgraphviz-dev chromium"
# The database layer: PostgreSQL's client library, and its server for the tests.
PACKAGES="$PACKAGES libpq-dev postgresql"
# The Python package (pybind11, Debian's python3 with venv and pip; pytest, numpy for tables).
PACKAGES="$PACKAGES pybind11-dev python3-dev python3-pytest python3-numpy python3-venv python3-pip python3-setuptools python3-wheel"
# The man page (help2man, rendered by man-db in its test) and the bash completion.
PACKAGES="$PACKAGES help2man man-db bash-completion"
# Optional groups: `fuzz` (clang, and compiler-rt's libFuzzer and sanitizer runtimes), `tidy` for
# tools/tidy.sh, `coverage` for tools/coverage.sh.
case "${1:-}" in
fuzz) PACKAGES="$PACKAGES clang libclang-rt-dev" ;;
tidy) PACKAGES="$PACKAGES clang-tidy" ;;
coverage) PACKAGES="$PACKAGES gcovr" ;;
esac

missing=""
for p in $PACKAGES; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done
[ -z "$missing" ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "catplan: these Debian packages are missing and I am not root (no sudo):$missing" >&2
    exit 1
fi
echo "catplan: installing missing Debian packages:$missing"
$SUDO apt-get update -q
# shellcheck disable=SC2086
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends $missing
