# Small schemas for the ontology-map cases (imported only).
@present Blocks(FreeSchema) begin
  (Block, Gripper, On)::Ob
  isHolding::Hom(Gripper, Block)
  (on_l, on_r)::Hom(On, Block)
  below::Hom(Block, Block)
  Color::AttrType(String)
  hasColor::Attr(Block, Color)
end

@present Kitchen(FreeSchema) begin
  (Object, Gripper, InReceptacle, Knife)::Ob
  isHolding::Hom(Gripper, Object)
  inReceptacle_l::Hom(InReceptacle, Object)
  knifeIsObject::Hom(Knife, Object)
  Mass::AttrType(Float64)
  Label::AttrType(String)
  knifeHasMass::Attr(Knife, Mass)
  knifeHasLabel::Attr(Knife, Label)
end

@present Stack(FreeSchema) begin
  (Top, Item)::Ob
  top::Hom(Top, Item)
  down::Hom(Item, Item)
  under::Hom(Top, Item)
  top ⋅ down == under
end
