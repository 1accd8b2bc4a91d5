transfer examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --problem CaseStudy --plan tests/cli/bad/plan/encoding.plan --format json -o build/bad_plan_transfer.json
absent: build/bad_plan_transfer.json
