@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
# Arithmetic on a Bool, and a Bool computed for an Int attribute.
@rule bump(a, b) on S begin
  Pre => begin
    (a, b)::Thing
  end
  Keep => begin
    (a, b)::Thing
  end
  Eff => begin
    (a, b)::Thing
    size(a) == flag(a) + 1
    size(b) == (size(a) < 3)
  end
end
