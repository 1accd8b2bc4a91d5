report examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --problem CaseStudy --plan tests/cli/bad/plan/static.plan -o build/bad_plan_report.html
absent: build/bad_plan_report.html
