# The Kitchenworld ontology, verbatim from the paper's appendix (Schema Categories, Kitchenworld),
# except that the attribute types declare the value kinds the paper's ontology map gives them
# (Temperature => Float64, Mass => Float64, Material => String), so that files importing this one
# can write literals for them.

@present KitchenWorld(FreeSchema) begin
  # Parent Types
  Object::Ob
  Receptacle::Ob
  Empty::Ob
  Gripper::Ob

  # Robot
  isHolding::Hom(Gripper, Object)
  isEmpty::Hom(Empty, Object)

  # Attributes
  Temperature::AttrType(Float64)
  Mass::AttrType(Float64)
  Material::AttrType(String)

  # Relations
  InReceptacle::Ob
  inReceptacle_l::Hom(InReceptacle, Object)
  inReceptacle_r::Hom(InReceptacle, Receptacle)

  # Ingredients
  BreadSliced::Ob
  breadSlicedIsObject::Hom(BreadSliced, Object)
  breadSlicedIsReceptacle::Hom(
    BreadSliced, Receptacle)
  breadSlicedHasTemperature::Attr(
    BreadSliced, Temperature)
  breadSlicedHasMass::Attr(BreadSliced, Mass)
  breadSlicedHasMaterial::Attr(
    BreadSliced, Material)

  LettuceSliced::Ob
  lettuceSlicedIsObject::Hom(
    LettuceSliced, Object)
  lettuceSlicedIsReceptacle::Hom(
    LettuceSliced, Receptacle)
  lettuceSlicedHasTemperature::Attr(
    LettuceSliced, Temperature)
  lettuceSlicedHasMass::Attr(
    LettuceSliced, Mass)
  lettuceSlicedHasMaterial::Attr(
    LettuceSliced, Material)

  TomatoSliced::Ob
  tomatoSlicedIsObject::Hom(
    TomatoSliced, Object)
  tomatoSlicedIsReceptacle::Hom(
    TomatoSliced, Receptacle)
  tomatoSlicedHasTemperature::Attr(
    TomatoSliced, Temperature)
  tomatoSlicedHasMass::Attr(TomatoSliced, Mass)
  tomatoSlicedHasMaterial::Attr(
    TomatoSliced, Material)

  Plate::Ob
  plateIsObject::Hom(Plate, Object)
  plateIsReceptacle::Hom(Plate, Receptacle)
  plateHasTemperature::Attr(Plate, Temperature)
  plateHasMass::Attr(Plate, Mass)
  plateHasMaterial::Attr(
    Plate, Material)

  Knife::Ob
  knifeIsObject::Hom(Knife, Object)
  knifeHasTemperature::Attr(Knife, Temperature)
  knifeHasMass::Attr(Knife, Mass)
  knifeHasMaterial::Attr(
    Knife, Material)
end
