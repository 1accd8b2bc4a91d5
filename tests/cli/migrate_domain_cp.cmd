migrate-domain examples/pddl/blocks/three_to_four.cp --map ThreeToFour --domain blocks3 --format cp -o build/golden/migrate_domain_cp/blocks3_blocks4.cp
before: rm -rf build/golden/migrate_domain_cp && mkdir -p build/golden/migrate_domain_cp
after: D=build/golden/migrate_domain_cp; grep -c "@rule" $D/blocks3_blocks4.cp; $CATPLAN check $D/blocks3_blocks4.cp; echo "exit $?"; $CATPLAN migrate-domain examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen --domain Blocksworld --format cp -o $D/kitchen.cp 2>&1; echo "exit $?"; test -e $D/kitchen.cp || echo "no kitchen.cp written"
