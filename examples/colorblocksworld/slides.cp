# The ColorBlocksworld case study in the form of the paper authors' slides (AMS-JMM 2025):
# unary predicates are reified as predicate objects (IsClear, IsOnTable, HasColor, HasLabel) with
# a `...Dom` hom to Block, and "the hand is empty" is a distinguished `null` block.

@present OntColorBlocksworld(FreeSchema) begin
  # Types
  Block::Ob
  Empty::Ob
  Gripper::Ob

  HasColor::Ob
  IsClear::Ob
  IsOnTable::Ob
  HasLabel::Ob

  Color::AttrType
  Clear::AttrType
  OnTable::AttrType
  Label::AttrType

  # Predicates
  isEmpty::Hom(Empty, Block)
  isHolding::Hom(Gripper, Block)
  hasColor::Attr(HasColor, Color)
  hasColorDom::Hom(HasColor, Block)
  isClear::Attr(IsClear, Clear)
  isClearDom::Hom(IsClear, Block)
  isOnTable::Attr(IsOnTable, OnTable)
  isOnTableDom::Hom(IsOnTable, Block)
  hasLabel::Attr(HasLabel, Label)
  hasLabelDom::Hom(HasLabel, Block)

  # Relations
  On::Ob
  onL::Hom(On, Block)
  onR::Hom(On, Block)
end

# The initial state of the slides (the slides' duplicated line for onTableD is left out).
state = @acset_colim yOntColorBlocksworld begin
  gripper::Gripper
  empty::Empty

  null::Block
  isHolding(gripper) == null
  isEmpty(empty) == null
  (labelNull)::HasLabel
  hasLabelDom(labelNull) == null
  hasLabel(labelNull) == "null"

  (A, B, C, D, E, F)::Block
  (colorA, colorB, colorC, colorD, colorE, colorF)::HasColor
  hasColorDom(colorA) == A
  hasColorDom(colorB) == B
  hasColorDom(colorC) == C
  hasColorDom(colorD) == D
  hasColorDom(colorE) == E
  hasColorDom(colorF) == F
  hasColor(colorA) == "green"
  hasColor(colorB) == "red"
  hasColor(colorC) == "yellow"
  hasColor(colorD) == "purple"
  hasColor(colorE) == "purple"
  hasColor(colorF) == "blue"

  (labelA, labelB, labelC, labelD, labelE, labelF)::HasLabel
  hasLabelDom(labelA) == A
  hasLabelDom(labelB) == B
  hasLabelDom(labelC) == C
  hasLabelDom(labelD) == D
  hasLabelDom(labelE) == E
  hasLabelDom(labelF) == F
  hasLabel(labelA) == "A"
  hasLabel(labelB) == "B"
  hasLabel(labelC) == "C"
  hasLabel(labelD) == "D"
  hasLabel(labelE) == "E"
  hasLabel(labelF) == "F"

  (x1, x2)::On
  onL(x1) == E
  onR(x1) == D
  onL(x2) == D
  onR(x2) == C

  (clearA, clearB, clearC, clearD, clearE, clearF)::IsClear
  isClearDom(clearA) == A
  isClearDom(clearB) == B
  isClearDom(clearC) == C
  isClearDom(clearD) == D
  isClearDom(clearE) == E
  isClearDom(clearF) == F
  isClear(clearA) == true
  isClear(clearB) == true
  isClear(clearC) == false
  isClear(clearD) == false
  isClear(clearE) == true
  isClear(clearF) == true

  (onTableA, onTableB, onTableC, onTableD, onTableE, onTableF)::IsOnTable
  isOnTableDom(onTableA) == A
  isOnTableDom(onTableB) == B
  isOnTableDom(onTableC) == C
  isOnTableDom(onTableD) == D
  isOnTableDom(onTableE) == E
  isOnTableDom(onTableF) == F
  isOnTable(onTableA) == true
  isOnTable(onTableB) == true
  isOnTable(onTableC) == true
  isOnTable(onTableD) == false
  isOnTable(onTableE) == false
  isOnTable(onTableF) == true
end

# The goal: a tower coloured, from top to bottom, purple, green, red, purple, yellow.
goal = @acset_colim yOntColorBlocksworld begin
  (top, second, middle, fourth, bottom)::Block
  (c1, c2, c3, c4, c5)::HasColor
  hasColorDom(c1) == top;    hasColor(c1) == "purple"
  hasColorDom(c2) == second; hasColor(c2) == "green"
  hasColorDom(c3) == middle; hasColor(c3) == "red"
  hasColorDom(c4) == fourth; hasColor(c4) == "purple"
  hasColorDom(c5) == bottom; hasColor(c5) == "yellow"
  (on1, on2, on3, on4)::On
  onL(on1) == top;    onR(on1) == second
  onL(on2) == second; onR(on2) == middle
  onL(on3) == middle; onR(on3) == fourth
  onL(on4) == fourth; onR(on4) == bottom
end

# unstack as on the slides, but without their stale fact: L also matches underblock's
# `IsClear == false` part, so the rule deletes it before R creates `IsClear == true`. K holds
# the blocks only, so the gripper, the Empty part and the predicate parts are deleted and
# created anew. In `l` and `r`, the names on the left are K's, those on the right L's and R's.
unstack = @migration SchRule OntColorBlocksworld begin
  L => @join begin
    gripper::Gripper
    empty::Empty
    (block, underblock, null)::Block
    isEmpty(empty) == null

    o::On
    onL(o) == block
    onR(o) == underblock

    isHolding(gripper) == null

    clearblock::IsClear
    isClearDom(clearblock) == block
    isClear(clearblock) == true

    clearunderblock::IsClear
    isClearDom(clearunderblock) == underblock
    isClear(clearunderblock) == false
  end
  K => @join begin
    (block, underblock, null)::Block
  end
  R => @join begin
    gripper::Gripper
    empty::Empty
    (block, underblock, null)::Block
    isEmpty(empty) == null

    isHolding(gripper) == block

    clearunderblock::IsClear
    isClearDom(clearunderblock) == underblock
    isClear(clearunderblock) == true
  end
  l => begin
    null => null
    block => block
    underblock => underblock
  end
  r => begin
    null => null
    block => block
    underblock => underblock
  end
end

# stack: holding block, underblock clear -> block on underblock, underblock not clear, block
# clear, the hand empty (holding null).
stack = @migration SchRule OntColorBlocksworld begin
  L => @join begin
    gripper::Gripper
    empty::Empty
    (block, underblock, null)::Block
    isEmpty(empty) == null
    isHolding(gripper) == block

    clearunderblock::IsClear
    isClearDom(clearunderblock) == underblock
    isClear(clearunderblock) == true
  end
  K => @join begin
    (block, underblock, null)::Block
  end
  R => @join begin
    gripper::Gripper
    empty::Empty
    (block, underblock, null)::Block
    isEmpty(empty) == null
    isHolding(gripper) == null

    o::On
    onL(o) == block
    onR(o) == underblock

    clearblock::IsClear
    isClearDom(clearblock) == block
    isClear(clearblock) == true

    clearunderblock::IsClear
    isClearDom(clearunderblock) == underblock
    isClear(clearunderblock) == false
  end
  l => begin
    null => null
    block => block
    underblock => underblock
  end
  r => begin
    null => null
    block => block
    underblock => underblock
  end
end

# pickup: the hand is empty, block clear and on the table -> holding block (which has no
# IsClear part while held, as after unstack), not on the table.
pickup = @migration SchRule OntColorBlocksworld begin
  L => @join begin
    gripper::Gripper
    empty::Empty
    (block, null)::Block
    isEmpty(empty) == null
    isHolding(gripper) == null

    clearblock::IsClear
    isClearDom(clearblock) == block
    isClear(clearblock) == true

    tbl::IsOnTable
    isOnTableDom(tbl) == block
    isOnTable(tbl) == true
  end
  K => @join begin
    (block, null)::Block
  end
  R => @join begin
    gripper::Gripper
    empty::Empty
    (block, null)::Block
    isEmpty(empty) == null
    isHolding(gripper) == block

    tbl::IsOnTable
    isOnTableDom(tbl) == block
    isOnTable(tbl) == false
  end
  l => begin
    null => null
    block => block
  end
  r => begin
    null => null
    block => block
  end
end

# putdown: holding block -> block on the table and clear, the hand empty.
putdown = @migration SchRule OntColorBlocksworld begin
  L => @join begin
    gripper::Gripper
    empty::Empty
    (block, null)::Block
    isEmpty(empty) == null
    isHolding(gripper) == block

    tbl::IsOnTable
    isOnTableDom(tbl) == block
    isOnTable(tbl) == false
  end
  K => @join begin
    (block, null)::Block
  end
  R => @join begin
    gripper::Gripper
    empty::Empty
    (block, null)::Block
    isEmpty(empty) == null
    isHolding(gripper) == null

    clearblock::IsClear
    isClearDom(clearblock) == block
    isClear(clearblock) == true

    tbl::IsOnTable
    isOnTableDom(tbl) == block
    isOnTable(tbl) == true
  end
  l => begin
    null => null
    block => block
  end
  r => begin
    null => null
    block => block
  end
end

# The domain lists the actions with their parameters: the plan binds block and underblock;
# null is found by the search (it is what the gripper holds, or what `empty` marks).
@domain SlidesBlocksworld(OntColorBlocksworld) begin
  unstack(block, underblock)
  putdown(block)
  pickup(block)
  stack(block, underblock)
end

@problem SlidesCaseStudy(SlidesBlocksworld) begin
  initial = state
  goal = goal
end
