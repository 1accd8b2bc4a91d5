# The paper's ontology map F : Kitchenworld -> ColorBlocksworld (§V.B), written as in the paper:
# target schema first, then source. Each Kitchenworld type goes to a ColorBlocksworld type or to a
# conjunctive query (the blocks of one colour); Kitchenworld's attributes, which ColorBlocksworld
# has no notion of, get constant defaults. Clear and OnTable are not carried (a lossy map).
#
#   catplan migrate examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen Initial
#
# prints the paper's Table 1, right column.

@import "../colorblocksworld/colorblocksworld.cp"
@import "../kitchenworld/kitchenworld.cp"

@migration ColorToKitchen(KitchenWorld, ColorBlocksworld) begin
  # types
  Gripper => Gripper
  Empty => Empty
  Object => Block
  Receptacle => Block
  InReceptacle => On
  # predicates
  isHolding => isHolding
  isEmpty => isEmpty
  inReceptacle_l => on_l
  inReceptacle_r => on_r
  # attribute types: value kinds alone, so their attributes are constants
  Temperature => Float64
  Mass => Float64
  Material => String

  # colour => ingredient or utensil
  BreadSliced => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "purple")
  end
  breadSlicedIsObject => block
  breadSlicedIsReceptacle => block
  breadSlicedHasTemperature => (x -> 0.0)
  breadSlicedHasMass => (x -> 0.0)
  breadSlicedHasMaterial => (x -> "Unknown")

  TomatoSliced => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "red")
  end
  tomatoSlicedIsObject => block
  tomatoSlicedIsReceptacle => block
  tomatoSlicedHasTemperature => (x -> 0.0)
  tomatoSlicedHasMass => (x -> 0.0)
  tomatoSlicedHasMaterial => (x -> "Unknown")

  LettuceSliced => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "green")
  end
  lettuceSlicedIsObject => block
  lettuceSlicedIsReceptacle => block
  lettuceSlicedHasTemperature => (x -> 0.0)
  lettuceSlicedHasMass => (x -> 0.0)
  lettuceSlicedHasMaterial => (x -> "Unknown")

  Plate => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "yellow")
  end
  plateIsObject => block
  plateIsReceptacle => block
  plateHasTemperature => (x -> 0.0)
  plateHasMass => (x -> 0.0)
  plateHasMaterial => (x -> "Unknown")

  Knife => @join begin
    block::Block
    C::Color
    (hc:block → C)::hasColor
    (c:block → C)::(block -> "blue")
  end
  knifeIsObject => block
  knifeHasTemperature => (x -> 0.0)
  knifeHasMass => (x -> 0.0)
  knifeHasMaterial => (x -> "Unknown")
end
