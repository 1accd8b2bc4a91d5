# The 4-operator blocks world's plans in the 3-operator one: the map forgets the gripper. No
# 3-operator action is a migrated 4-operator one, so every step is repaired: unstack and
# move-to-table, pick-up becomes no step (the block is still on the table in the target), and
# the stack after it is move-from-table, so pairs of source steps merge into one.
@import "blocks4.pddl"
@import "blocks3.pddl"

@migration FourToThree(blocks3, blocks4) begin
  object => object
  block => block
  on => on
  on-table => on-table
  clear => clear
end
