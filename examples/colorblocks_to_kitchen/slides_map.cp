# The paper's ontology map F : Kitchenworld -> ColorBlocksworld for the slide form of
# ColorBlocksworld (../colorblocksworld/slides.cp), where a colour is a HasColor predicate object
# with a hom hasColorDom to its block: a coloured block is the join of a Block, a HasColor on it and
# its Color.
#
#   catplan migrate examples/colorblocks_to_kitchen/slides_map.cp --map ColorToKitchen state

@import "../colorblocksworld/slides.cp"
@import "../kitchenworld/kitchenworld.cp"

ColorToKitchen = @migration KitchenWorld OntColorBlocksworld begin
  # types
  Gripper => Gripper
  Empty => Empty
  Object => Block
  Receptacle => Block
  InReceptacle => On
  # predicates
  isHolding => isHolding
  isEmpty => isEmpty
  inReceptacle_l => onL
  inReceptacle_r => onR
  # attribute types
  Temperature => Float64
  Mass => Float64
  Material => String

  # colour => ingredient or utensil
  BreadSliced => @join begin
    block::Block
    c::HasColor
    C::Color
    (d: c → block)::hasColorDom
    (f: c → C)::hasColor
    (g: c → C)::(x -> "purple")
  end
  breadSlicedIsObject => block
  breadSlicedIsReceptacle => block
  breadSlicedHasTemperature => (x -> 0.0)
  breadSlicedHasMass => (x -> 0.0)
  breadSlicedHasMaterial => (x -> "Unknown")

  TomatoSliced => @join begin
    block::Block
    c::HasColor
    C::Color
    (d: c → block)::hasColorDom
    (f: c → C)::hasColor
    (g: c → C)::(x -> "red")
  end
  tomatoSlicedIsObject => block
  tomatoSlicedIsReceptacle => block
  tomatoSlicedHasTemperature => (x -> 0.0)
  tomatoSlicedHasMass => (x -> 0.0)
  tomatoSlicedHasMaterial => (x -> "Unknown")

  LettuceSliced => @join begin
    block::Block
    c::HasColor
    C::Color
    (d: c → block)::hasColorDom
    (f: c → C)::hasColor
    (g: c → C)::(x -> "green")
  end
  lettuceSlicedIsObject => block
  lettuceSlicedIsReceptacle => block
  lettuceSlicedHasTemperature => (x -> 0.0)
  lettuceSlicedHasMass => (x -> 0.0)
  lettuceSlicedHasMaterial => (x -> "Unknown")

  Plate => @join begin
    block::Block
    c::HasColor
    C::Color
    (d: c → block)::hasColorDom
    (f: c → C)::hasColor
    (g: c → C)::(x -> "yellow")
  end
  plateIsObject => block
  plateIsReceptacle => block
  plateHasTemperature => (x -> 0.0)
  plateHasMass => (x -> 0.0)
  plateHasMaterial => (x -> "Unknown")

  Knife => @join begin
    block::Block
    c::HasColor
    C::Color
    (d: c → block)::hasColorDom
    (f: c → C)::hasColor
    (g: c → C)::(x -> "blue")
  end
  knifeIsObject => block
  knifeHasTemperature => (x -> 0.0)
  knifeHasMass => (x -> 0.0)
  knifeHasMaterial => (x -> "Unknown")
end
