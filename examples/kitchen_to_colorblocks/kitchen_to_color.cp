# Pattern (a), specific to abstract, |target| < |source|: a SandwichKitchen plan carried into
# ColorBlocksworld. Every kitchen thing becomes a Block, whatever ingredient or utensil it was:
# the distinctions between bread, tomato, lettuce and plate merge into the one type Block, and
# the temperatures are lost. What is left of a thing's kind is its material, which becomes the
# block's colour. The map is a functor (every type to a type, every predicate to a predicate), so
# the migration is Δ_F and each migrated step applies by construction.
#
#   catplan transfer examples/kitchen_to_colorblocks/kitchen_to_color.cp --map KitchenToColor \
#       --problem MakeSandwich --plan examples/sandwich_kitchen/sandwich.plan

@import "../colorblocksworld/colorblocksworld.cp"
@import "../sandwich_kitchen/sandwich_kitchen.cp"

@migration KitchenToColor(ColorBlocksworld, SandwichKitchen) begin
  # types
  Block => Object
  Empty => Empty
  Gripper => Gripper
  On => InReceptacle
  # predicates
  on_l => inReceptacle_l
  on_r => inReceptacle_r
  isEmpty => isEmpty
  isHolding => isHolding
  # attributes
  Color => Material
  Clear => Free
  OnTable => OnCounter
  hasColor => hasMaterial
  isClear => isFree
  isOnTable => isOnCounter
end
