@import "shared_imported.cp"
@import "../../examples/kitchenworld/kitchenworld.cp"

@acset_colim K(KitchenWorld) begin
  k::Knife
  knifeHasMass(k) == 0.5
end
