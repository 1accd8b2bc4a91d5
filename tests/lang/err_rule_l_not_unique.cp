@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
# The slide form with an explicit l that leaves K's y unmapped: y may go to x, y or z.
choose = @migration SchRule S begin
  L => @join begin
    (x, y, z)::Thing
  end
  K => @join begin
    (x, y)::Thing
  end
  R => @join begin
    (x, y)::Thing
  end
  l => begin
    x => x
  end
end
