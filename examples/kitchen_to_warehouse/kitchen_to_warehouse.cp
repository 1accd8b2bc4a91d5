# Pattern (b), specific to abstract to specific: a SandwichKitchen plan carried into the
# Warehouse domain through ColorBlocksworld, as one composed map. KitchenToColor distils the
# kitchen plan into a blocks plan (every thing a Block, its material its colour); ColorToWarehouse
# tailors a blocks plan to crates and a forklift, and splits off the fragile crates: the blocks
# whose colour is "ceramic" (a conjunctive query). KitchenToWarehouse = KitchenToColor ∘
# ColorToWarehouse goes from the kitchen to the warehouse in one step; migrating along it is
# migrating along KitchenToColor, then along ColorToWarehouse.
#
#   catplan transfer examples/kitchen_to_warehouse/kitchen_to_warehouse.cp \
#       --map KitchenToWarehouse --problem MakeSandwich \
#       --plan examples/sandwich_kitchen/sandwich.plan --rename-by-type

@import "../kitchen_to_colorblocks/kitchen_to_color.cp"
@import "../warehouse/warehouse.cp"

@migration ColorToWarehouse(Warehouse, ColorBlocksworld) begin
  # types
  Crate => Block
  Idle => Empty
  Forklift => Gripper
  Stacked => On
  # predicates
  isCarrying => isHolding
  isIdle => isEmpty
  stacked_top => on_l
  stacked_bottom => on_r
  # attributes
  Accessible => Clear
  OnFloor => OnTable
  Contents => Color
  isAccessible => isClear
  isOnFloor => isOnTable
  hasContents => hasColor
  # fragile crates: a query with a colour filter, and a constant load limit
  FragileCrate => @join begin
    block::Block
    hasColor(block) == "ceramic"
  end
  fragileIsCrate => block
  Load => Float64
  fragileMaxLoad => (x -> 20.0)
end

@compose KitchenToWarehouse(KitchenToColor, ColorToWarehouse)
