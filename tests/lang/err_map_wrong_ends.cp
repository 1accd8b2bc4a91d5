# The paper's kind of slip: Gripper sent to Block, so isHolding => isHolding no longer starts at
# the right object; and a hom sent to a path that ends at the wrong object.
@import "maps_part.cp"

@migration Bad(Kitchen, Blocks) begin
  Gripper => Block
  Object => Block
  InReceptacle => On
  isHolding => isHolding
  inReceptacle_l => on_l
  Knife => Gripper
  knifeIsObject => id(Gripper)
  Mass => Float64
  knifeHasMass => (x -> 0.5)
  Label => Color
  knifeHasLabel => (x -> "k")
end
