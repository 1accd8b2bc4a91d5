@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
# `c` is not a generator of Pre.
@rule take(a, c) on S begin
  Pre => begin
    a::Thing
  end
end
@rule give on S begin
  Pre => begin
    a::Thing
    h::Holder
    holds(h) == a
  end
end
# `holds` is a hom, not a part generator of give's precondition.
@domain D(S) begin
  give(a, holds)
end
