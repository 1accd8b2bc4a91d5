@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
# Keep names a part that Pre does not have.
@rule keep(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    (a, b)::Thing
  end
end
