@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
# A block name that is neither Pre, Keep, Eff, NAC nor PAC.
@rule move(a) on S begin
  Pre => begin
    a::Thing
  end
  Post => begin
    a::Thing
  end
end
