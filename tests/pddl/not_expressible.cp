# A domain `catplan pddl export` refuses, with the reason: `paint` makes a new block of a known
# colour, an object that PDDL cannot create (only a marker, whose values are unknown, can be made).
@present Paint(FreeSchema) begin
  Block::Ob
  On::Ob
  (on_l, on_r)::Hom(On, Block)
  Color::AttrType(String)
  hasColor::Attr(Block, Color)
end

@domain PaintDomain(Paint) begin
  @rule paint(base) begin
    Pre => begin
      base::Block
    end
    Keep => begin
      base::Block
    end
    Eff => begin
      base::Block
      top::Block
      hasColor(top) == "red"
      o::On
      on_l(o) == top; on_r(o) == base
    end
  end
end
