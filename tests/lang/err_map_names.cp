# Names are resolved in the right schema: target generators on the left, source ones on the right,
# query variables inside a query; an identity image is a warning.
@import "maps_part.cp"

@migration Names(Kitchen, Blocks) begin
  Gripper => Gripper
  Objekt => Block
  Object => Block
  InReceptacle => Onn
  isHolding => isHolding
  inReceptacle_l => on_l
  Knife => @join begin
    block::Block
    hasColour(block) == "blue"
    hasColor(blok) == "blue"
  end
  knifeIsObject => (Objct => block)
  Mass => Float64
  knifeHasMass => (x -> 0.5)
  Label => Colour
  knifeHasLabel => (x -> "k")
end

@compose Both(Names, Nope)
