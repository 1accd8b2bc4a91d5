migrate-domain examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --domain Blocksworld --format json
