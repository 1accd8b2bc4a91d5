# Ontology maps: plain entries, paths, a filter query and a hom onto one of its variables, a value
# kind with a constant, an attribute sent to a term, @product / @unit / @empty, and composition.
@import "maps_part.cp"

@migration Good(Kitchen, Blocks) begin
  Gripper => Gripper
  Object => Block
  InReceptacle => On
  isHolding => isHolding
  inReceptacle_l => on_l ⋅ below
  Knife => @join (block::Block; hasColor(block) == "blue")
  knifeIsObject => block
  Mass => Float64
  knifeHasMass => (x -> 0.5)
  Label => Color
  knifeHasLabel => hasColor(block)
end

StackOnBlocks = @migration Stack Blocks begin
  Top => On
  Item => Block
  top => on_l
  down => below
  under => on_l . below
end

@present Hand(FreeSchema) begin
  (H, T)::Ob
  holds::Hom(H, T)
end

# Hand -> Kitchen by a delta map; Good ∘ Hold migrates along Good, then along Hold.
@migration Hold(Hand, Kitchen) begin
  H => Gripper
  T => Object
  holds => isHolding
end

@compose GoodThenHold(Good, Hold)

@present Shapes(FreeSchema) begin
  (P, B, U, Z)::Ob
  (fst, snd)::Hom(P, B)
  bang::Hom(B, U)
  z::Hom(Z, B)
end

@migration Products(Shapes, Blocks) begin
  B => Block
  P => @product begin
    a::Block
    b::Block
  end
  fst => (B => a)
  snd => begin B => b end
  U => @unit
  bang => ()
  Z => @empty
end
