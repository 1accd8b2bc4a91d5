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
