@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
@rule touch(a) on S begin
  Pre => begin
    a::Thing
  end
end
# A second rule with the same name.
@rule touch(b) on S begin
  Pre => begin
    b::Thing
  end
end
