# Pattern (d), a delta case: the case study's plan carried from ColorBlocksworld into plain
# Blocksworld, the PDDL domain without colours. Every Blocksworld type goes to a type, every
# predicate to a predicate and every attribute to an attribute (no query), so the map is a
# functor and the migration is Δ_F: it preserves pushouts, so each migrated step applies by
# construction (the paper's Appendix A). The colours are forgotten, and with them the reason the
# goal tower is ordered as it is.
#
#   catplan transfer examples/colorblocks_to_blocks/forget_colors.cp --map ForgetColors \
#       --problem CaseStudy --plan examples/colorblocksworld/paper.plan

@import "../colorblocksworld/colorblocksworld.cp"

@present PlainBlocksworld(FreeSchema) begin
  Block::Ob
  Empty::Ob
  Gripper::Ob
  Clear::AttrType
  OnTable::AttrType
  On::Ob
  on_l::Hom(On, Block)
  on_r::Hom(On, Block)
  isEmpty::Hom(Empty, Block)
  isHolding::Hom(Gripper, Block)
  isClear::Attr(Block, Clear)
  isOnTable::Attr(Block, OnTable)
end

@migration ForgetColors(PlainBlocksworld, ColorBlocksworld) begin
  Block => Block
  Empty => Empty
  Gripper => Gripper
  On => On
  on_l => on_l
  on_r => on_r
  isEmpty => isEmpty
  isHolding => isHolding
  Clear => Clear
  OnTable => OnTable
  isClear => isClear
  isOnTable => isOnTable
end

# A goal stated in plain Blocksworld: a tower of three, the top one clear. Pushed back to
# ColorBlocksworld along the same map (Σ, the left adjoint of Δ), it is the ColorBlocksworld goal
# whose states are exactly those that migrate to a state with such a tower:
#
#   catplan migrate examples/colorblocks_to_blocks/forget_colors.cp --map ForgetColors \
#       PlainTower --sigma
@acset_colim PlainTower(PlainBlocksworld) begin
  (top, middle, bottom)::Block
  (o1, o2)::On
  on_l(o1) == top; on_r(o1) == middle
  on_l(o2) == middle; on_r(o2) == bottom
  isClear(top) == true
end
