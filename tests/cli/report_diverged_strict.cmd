report tests/cli/transfer/relabel.cp --map Sorted --problem Restock --goal Stocked --no-timing --plan tests/cli/transfer/relabel.plan --strict -o build/report_diverged_strict.html
