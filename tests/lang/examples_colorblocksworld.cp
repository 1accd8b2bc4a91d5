# The case-study files load as written.
@import "../../examples/colorblocksworld/colorblocksworld.cp"
@import "../../examples/kitchenworld/kitchenworld.cp"
