#!/bin/sh
# Runs the fuzz harnesses of the fuzz preset (docs/fuzzing.md), one after the other.
#   fuzz/run.sh SECONDS [HARNESS...]     default: every harness
# Each runs for SECONDS from its seed corpus (build/fuzz/fuzz-seeds/NAME, made from the repository by
# the build) and its working corpus (build/fuzz/corpus/NAME, kept between runs), at nice 19. A crash,
# a sanitizer report, a leak, a timeout (10 s on one input) or an out-of-memory (2 GB) stops it and
# leaves the input in build/fuzz/artifacts/NAME/; the script then exits non-zero after the others ran.
set -u
cd "$(dirname "$0")/.."
seconds=${1:?usage: fuzz/run.sh SECONDS [HARNESS...]}
shift
harnesses=${*:-lang json pddl_domain pddl_problem ipc_plan plan transfer}
build=build/fuzz
status=0
for h in $harnesses; do
    mkdir -p "$build/corpus/$h" "$build/artifacts/$h"
    echo "fuzz: $h for ${seconds}s"
    if ! nice -n 19 "$build/fuzz/fuzz_$h" -max_total_time="$seconds" -timeout=10 \
        -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
        -artifact_prefix="$build/artifacts/$h/" \
        "$build/corpus/$h" "$build/fuzz-seeds/$h" >"$build/artifacts/$h.log" 2>&1; then
        echo "fuzz: $h FAILED; the end of its log ($build/artifacts/$h.log):"
        tail -n 40 "$build/artifacts/$h.log"
        for f in "$build/artifacts/$h"/*; do
            [ -f "$f" ] || continue
            echo "fuzz: the input, $f (as a Python bytes literal):"
            python3 -c 'import sys; print(repr(open(sys.argv[1], "rb").read()[:4096]))' "$f"
        done
        status=1
    else
        grep -E "^stat::number_of_executed_units|^#[0-9]+.*DONE" "$build/artifacts/$h.log" | tail -n 2
    fi
done
exit $status
