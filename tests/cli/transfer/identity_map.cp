# A map with an entry that draws a warning: `itself` is sent to an identity (the hom of a Block to
# itself). The transfer prints each warning of its inputs once.

@import "../../../examples/colorblocksworld/colorblocksworld.cp"

@present SelfBlocks(FreeSchema) begin
  Block::Ob
  Empty::Ob
  Gripper::Ob
  On::Ob
  on_l::Hom(On, Block)
  on_r::Hom(On, Block)
  isEmpty::Hom(Empty, Block)
  isHolding::Hom(Gripper, Block)
  itself::Hom(Block, Block)
end

@migration Itself(SelfBlocks, ColorBlocksworld) begin
  Block => Block
  Empty => Empty
  Gripper => Gripper
  On => On
  on_l => on_l
  on_r => on_r
  isEmpty => isEmpty
  isHolding => isHolding
  itself => Block
end
