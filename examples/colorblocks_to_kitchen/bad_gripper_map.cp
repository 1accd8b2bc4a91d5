# Pattern (e), a map that is no functor: the paper's nonsensical analogy of §VI.B, the Kitchenworld
# Gripper sent to a Block. The map is ColorToKitchen (appendix_map.cp) but for that one entry.
# Then isHolding : Gripper -> Object would need an image from Block to Block, and ColorBlocksworld
# has no such predicate: the map is rejected where it is written, before any plan is touched.
#
#   catplan check examples/colorblocks_to_kitchen/bad_gripper_map.cp     # exit 2, located errors

@import "../colorblocksworld/colorblocksworld.cp"
@import "../kitchenworld/kitchenworld.cp"

@migration GripperToBlock(KitchenWorld, ColorBlocksworld) begin
  Gripper => Block
  Empty => Empty
  Object => Block
  Receptacle => Block
  InReceptacle => On
  isHolding => isHolding
  isEmpty => isEmpty
  inReceptacle_l => on_l
  inReceptacle_r => on_r
  Temperature => Float64
  Mass => Float64
  Material => String
  BreadSliced => @join (block::Block; hasColor(block) == "purple")
  breadSlicedIsObject => block
  breadSlicedIsReceptacle => block
  breadSlicedHasTemperature => (x -> 0.0)
  breadSlicedHasMass => (x -> 0.0)
  breadSlicedHasMaterial => (x -> "Unknown")
  TomatoSliced => @join (block::Block; hasColor(block) == "red")
  tomatoSlicedIsObject => block
  tomatoSlicedIsReceptacle => block
  tomatoSlicedHasTemperature => (x -> 0.0)
  tomatoSlicedHasMass => (x -> 0.0)
  tomatoSlicedHasMaterial => (x -> "Unknown")
  LettuceSliced => @join (block::Block; hasColor(block) == "green")
  lettuceSlicedIsObject => block
  lettuceSlicedIsReceptacle => block
  lettuceSlicedHasTemperature => (x -> 0.0)
  lettuceSlicedHasMass => (x -> 0.0)
  lettuceSlicedHasMaterial => (x -> "Unknown")
  Plate => @join (block::Block; hasColor(block) == "yellow")
  plateIsObject => block
  plateIsReceptacle => block
  plateHasTemperature => (x -> 0.0)
  plateHasMass => (x -> 0.0)
  plateHasMaterial => (x -> "Unknown")
  Knife => @join (block::Block; hasColor(block) == "blue")
  knifeIsObject => block
  knifeHasTemperature => (x -> 0.0)
  knifeHasMass => (x -> 0.0)
  knifeHasMaterial => (x -> "Unknown")
end
