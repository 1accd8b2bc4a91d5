# The 3-operator blocks world's plans in the 4-operator one: the hand is always empty between
# steps (hand-empty is the one-tuple query) and never holds a block. A move is no 4-operator
# action, so it is repaired: unstack then stack, or pick-up then stack, one source step
# becoming two target steps.
@import "blocks3.pddl"
@import "blocks4.pddl"

@migration ThreeToFour(blocks4, blocks3) begin
  object => object
  block => block
  on => on
  on-table => on-table
  clear => clear
  hand-empty => @unit
  holding => @empty
end
