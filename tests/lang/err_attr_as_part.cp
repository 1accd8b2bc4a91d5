@present Blocks(FreeSchema) begin
  (Block, Gripper, On)::Ob
  isHolding::Hom(Gripper, Block)
  (on_l, on_r)::Hom(On, Block)
  Color::AttrType
  Clear::AttrType(Bool)
  hasColor::Attr(Block, Color)
  isClear::Attr(Block, Clear)
end

@acset_colim I(Blocks) begin
  A::Block
  g::Gripper
  isHolding(g) == hasColor(A)
end
