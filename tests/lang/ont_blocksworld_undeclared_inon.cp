# The paper's appendix OntBlocksworld, verbatim: it uses InOn without declaring it.
# Both on_l and on_r must be reported.
@present OntBlocksworld(FreeSchema) begin
  # Parent Types
  Block::Ob
  Empty::Ob
  Gripper::Ob

  # Attributes
  Color::AttrType
  Clear::AttrType
  OnTable::AttrType

  # Relations 
  On::Ob
  on_l::Hom(InOn, Block)
  on_r::Hom(InOn, Block)

  # Robot
  isEmpty::Hom(Empty, Block)
  isHolding::Hom(Gripper, Block)

  # Blocks
  hasColor::Attr(Block, Color)
  isClear::Attr(Block, Clear)
  isOnTable::Attr(Block, OnTable)
end
