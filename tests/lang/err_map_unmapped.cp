# Generators without an image are reported at the map's name, all at once.
@import "maps_part.cp"

@migration Partial(Kitchen, Blocks) begin
  Gripper => Gripper
  Object => Block
  isHolding => isHolding
end
