# The ColorBlocksworld ontology: the paper's appendix OntBlocksworld with the relation object
# `On` used consistently (the appendix declares `On` but types on_l and on_r with `InOn`).

@present ColorBlocksworld(FreeSchema) begin
  # Parent Types
  Block::Ob
  Empty::Ob
  Gripper::Ob

  # Attributes
  Color::AttrType
  Clear::AttrType
  OnTable::AttrType

  # Relations
  On::Ob
  on_l::Hom(On, Block)
  on_r::Hom(On, Block)

  # Robot
  isEmpty::Hom(Empty, Block)
  isHolding::Hom(Gripper, Block)

  # Blocks
  hasColor::Attr(Block, Color)
  isClear::Attr(Block, Clear)
  isOnTable::Attr(Block, OnTable)
end

# The case study's initial state (the paper's Table 1, left column). The gripper holds the
# "empty" block: isHolding(gripper) and isEmpty(empty) name the same new, unnamed block, whose
# colour, isClear and isOnTable stay unknown (variables).
@acset_colim Initial(ColorBlocksworld) begin
  # Initial state
  gripper::Gripper
  empty::Empty
  isHolding(gripper) == isEmpty(empty)
  (A, B, C, D, E, F)::Block
  hasColor(A) == "green"
  hasColor(B) == "red"
  hasColor(C) == "yellow"
  hasColor(D) == "purple"
  hasColor(E) == "purple"
  hasColor(F) == "blue"
  (x1, x2)::On
  on_l(x1) == E
  on_r(x1) == D
  on_l(x2) == D
  on_r(x2) == C
  isOnTable(A) == true; isClear(A) == true
  isOnTable(B) == true; isClear(B) == true
  isOnTable(C) == true; isClear(C) == false
  isOnTable(D) == false; isClear(D) == false
  isOnTable(E) == false; isClear(E) == true
  isOnTable(F) == true; isClear(F) == true
end

# The case study's goal: a tower coloured, from top to bottom, purple, green, red, purple,
# yellow. Only the colours and the On relation are constrained; the other attributes are left
# unspecified, so they are unknowns that may match any value.
@acset_colim Goal(ColorBlocksworld) begin
  (top, second, middle, fourth, bottom)::Block
  hasColor(top) == "purple"
  hasColor(second) == "green"
  hasColor(middle) == "red"
  hasColor(fourth) == "purple"
  hasColor(bottom) == "yellow"
  (on1, on2, on3, on4)::On
  on_l(on1) == top;    on_r(on1) == second
  on_l(on2) == second; on_r(on2) == middle
  on_l(on3) == middle; on_r(on3) == fourth
  on_l(on4) == fourth; on_r(on4) == bottom
end

# The actions. Rule blocks are partial presentations: what a block does not mention is not
# constrained (Pre), is rewritten by Eff (Keep) or stays as it was (Eff, for a kept part). The
# parameters are the named blocks of Pre: unstack(block, underblock), pickup(block), ...
#
# "The hand is empty" is written as in the initial state: the gripper holds the same block as
# `empty` marks. Taking a block deletes `empty` and its marker block; putting one down creates
# new ones.
@domain Blocksworld(ColorBlocksworld) begin
  # unstack exactly as the paper lists it, except that the paper's undeclared InOn, inOn_l and
  # inOn_r are the schema's On, on_l and on_r, and that the paper calls the schema
  # OntBlocksworld.
  :unstack => @migration(ColorBlocksworld, begin
    Pre => @join begin
      gripper::Gripper
      empty::Empty
      (block, underblock)::Block
      o::On
      on_l(o) == block
      on_r(o) == underblock
      isClear(block) == true
      isHolding(gripper) == isEmpty(empty)
    end
    Keep => @join begin
      gripper::Gripper
      (block, underblock)::Block
    end
    Eff => @join begin
      gripper::Gripper
      (block, underblock)::Block
      isClear(underblock) == true
      isHolding(gripper) == block
    end
  end)

  # stack: holding block and underblock is clear -> block on underblock, underblock no longer
  # clear, the hand empty again.
  :stack => @migration(ColorBlocksworld, begin
    Pre => @join begin
      gripper::Gripper
      (block, underblock)::Block
      isHolding(gripper) == block
      isClear(underblock) == true
    end
    Keep => @join begin
      gripper::Gripper
      (block, underblock)::Block
    end
    Eff => @join begin
      gripper::Gripper
      empty::Empty
      (block, underblock)::Block
      o::On
      on_l(o) == block
      on_r(o) == underblock
      isClear(underblock) == false
      isHolding(gripper) == isEmpty(empty)
    end
  end)

  # pickup: the hand is empty and block is clear and on the table -> holding block, which is
  # no longer on the table.
  :pickup => @migration(ColorBlocksworld, begin
    Pre => @join begin
      gripper::Gripper
      empty::Empty
      block::Block
      isHolding(gripper) == isEmpty(empty)
      isClear(block) == true
      isOnTable(block) == true
    end
    Keep => @join begin
      gripper::Gripper
      block::Block
    end
    Eff => @join begin
      gripper::Gripper
      block::Block
      isHolding(gripper) == block
      isOnTable(block) == false
    end
  end)

  # putdown: holding block -> block on the table and clear, the hand empty again.
  :putdown => @migration(ColorBlocksworld, begin
    Pre => @join begin
      gripper::Gripper
      block::Block
      isHolding(gripper) == block
    end
    Keep => @join begin
      gripper::Gripper
      block::Block
    end
    Eff => @join begin
      gripper::Gripper
      empty::Empty
      block::Block
      isOnTable(block) == true
      isClear(block) == true
      isHolding(gripper) == isEmpty(empty)
    end
  end)
end

@problem CaseStudy(Blocksworld) begin
  initial = Initial
  goal = Goal
end
