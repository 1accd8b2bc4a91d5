transfer examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --problem CaseStudy --plan build/cli-batch-empty --plan tests/cli/transfer/batch/1-paper.plan
before: mkdir -p build/cli-batch-empty && rm -f build/cli-batch-empty/*
