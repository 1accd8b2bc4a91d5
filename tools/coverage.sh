#!/bin/sh
# Line coverage of the library by the tests: builds the `coverage` preset (gcc --coverage), runs
# every test, and prints gcovr's summary for src/catplan with the unit tests themselves left out.
# The report is in build/coverage/coverage.txt and, per file and line, build/coverage/html/.
set -eu
cd "$(dirname "$0")/.."
JOBS=${JOBS:-2}
./tools/install-deps.sh coverage
cmake --preset coverage >/dev/null
cmake --build --preset coverage -j "$JOBS"
# Counters add up across runs: start from zero.
find build/coverage -name '*.gcda' -delete
if ! ctest --preset coverage -j "$JOBS" >build/coverage/ctest.log 2>&1; then
    echo "coverage: some tests failed (build/coverage/ctest.log); the figure counts what ran" >&2
fi
tail -n 3 build/coverage/ctest.log
mkdir -p build/coverage/html
gcovr --root . --object-directory build/coverage -j "$JOBS" \
    --filter 'src/catplan/' --exclude '.*_test\.cpp$' \
    --txt build/coverage/coverage.txt --html-details build/coverage/html/index.html \
    --print-summary
