@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
# Pre merges a and b, so l would send two parts of Keep to one part of Pre.
@rule merge(a) on S begin
  Pre => begin
    (a, b)::Thing
    a == b
  end
  Keep => begin
    (a, b)::Thing
  end
  Eff => begin
    (a, b)::Thing
  end
end
