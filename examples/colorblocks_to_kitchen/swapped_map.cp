# Pattern (e), a map that is a functor but a wrong analogy: the paper's §VI.B swap of
# inReceptacle_l and inReceptacle_r. SwappedToKitchen is ColorToKitchen (appendix_map.cp) with
# the two predicates exchanged. It is accepted, and every step of the case study transfers, but
# "E on D" now reads "D in E": the stack is turned upside down. The migrated goal is swapped the
# same way, so it is reached; the goal the kitchen wants, Sandwich (stated in Kitchenworld), is
# not, and the transfer lists the statements it misses:
#
#   catplan transfer examples/colorblocks_to_kitchen/swapped_map.cp --map SwappedToKitchen \
#       --problem CaseStudy --plan examples/colorblocksworld/paper.plan --goal Sandwich
#
# With --map ColorToKitchen the same goal is satisfied.

@import "appendix_map.cp"
@import "../kitchenworld/sandwich_goal.cp"

@migration SwappedToKitchen(KitchenWorld, ColorBlocksworld) begin
  Gripper => Gripper
  Empty => Empty
  Object => Block
  Receptacle => Block
  InReceptacle => On
  isHolding => isHolding
  isEmpty => isEmpty
  # the swap
  inReceptacle_l => on_r
  inReceptacle_r => on_l
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
