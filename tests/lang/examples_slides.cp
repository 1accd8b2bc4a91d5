# The authors' slide form of the case study loads as written.
@import "../../examples/colorblocksworld/slides.cp"
