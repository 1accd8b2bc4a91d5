#!/bin/sh
# Runs every benchmark program of a release build with repetitions and prints medians.
# The machines are shared and noisy: compare medians and ratios measured in the same run.
set -eu
BUILD=${1:-build/release}
for b in "$BUILD"/bench/*_bench; do
    echo "== $b"
    "$b" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
         --benchmark_display_aggregates_only=true
done
