# top ⋅ down == under holds in Stack, but on_l is not on_r in Blocks; down sent to an identity
# is only a warning.
@import "maps_part.cp"

@migration StackOnBlocks(Stack, Blocks) begin
  Top => On
  Item => Block
  top => on_l
  down => id(Block)
  under => on_r
end
