@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
# Eff gives the new thing a named size that nothing binds.
@rule grow(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    a::Thing
    b::Thing
    n::Size
    size(b) == n
  end
end
