transfer examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --problem CaseStudy --plan tests/cli/transfer/batch --jobs 2 --no-timing
