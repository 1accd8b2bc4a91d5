# Mass holds Float64 values: a string default, a map to String, and a label that is not a string.
@import "maps_part.cp"

@migration Kinds(Kitchen, Blocks) begin
  Gripper => Gripper
  Object => Block
  InReceptacle => On
  isHolding => isHolding
  inReceptacle_l => on_l
  Knife => @join (block::Block; hasColor(block) == "blue")
  knifeIsObject => block
  Mass => String
  knifeHasMass => (x -> "heavy")
  Label => Color
  knifeHasLabel => (x -> 3)
end
