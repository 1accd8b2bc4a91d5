# Pattern (c), abstract to abstract: a Tower of Hanoi plan carried into a Blocksworld variant in
# which blocks move from where they stand onto any clear block or table spot (the three-operator
# "move" Blocksworld, with the table's spots as fixed blocks). Pegs become fixed spots, discs
# blocks; the map forgets Smaller, so the target's move has no size constraint and the Hanoi plan
# is one of its plans. The map is a functor, so the migration is Δ_F.
#
#   catplan transfer examples/hanoi_to_blocks/hanoi_to_blocks.cp --map HanoiToBlocks \
#       --problem ThreeDiscs --plan examples/hanoi/hanoi.plan

@import "../hanoi/hanoi.cp"

@present MoveBlocksworld(FreeSchema) begin
  Block::Ob
  On::Ob
  on_l::Hom(On, Block)
  on_r::Hom(On, Block)
  Clear::AttrType(Bool)
  Fixed::AttrType(Bool)
  isClear::Attr(Block, Clear)
  isFixed::Attr(Block, Fixed)
end

@migration HanoiToBlocks(MoveBlocksworld, Hanoi) begin
  Block => Place
  On => On
  on_l => on_top
  on_r => on_below
  Clear => Clear
  Fixed => Peg
  isClear => isClear
  isFixed => isPeg
end
