# The kitchen seen in coloured blocks, as the paper's Appendix map sees it (examples/
# colorblocks_to_kitchen/appendix_map.cp), between two PDDL domains: an item is a block, and each
# kind of item is a conjunctive query, the blocks of one colour (a join of `block` with a colour
# predicate). Stacking is the same in both domains, so every colour-blocks step is a kitchen
# step; the colour predicates become the kitchen's types.
@import "colorblocks.pddl"
@import "kitchen.pddl"

@migration BlocksToKitchen(kitchen, colorblocks) begin
  object => object
  item => block
  bread => @join begin
    b::block
    c::purple
    purple_1(c) == b
  end
  bread_is_item => b
  tomato => @join begin
    b::block
    c::red
    red_1(c) == b
  end
  tomato_is_item => b
  lettuce => @join begin
    b::block
    c::green
    green_1(c) == b
  end
  lettuce_is_item => b
  plate => @join begin
    b::block
    c::yellow
    yellow_1(c) == b
  end
  plate_is_item => b
  on => on
  on-counter => on-table
  free => clear
  hand-free => hand-empty
  holds => holding
end
