# Arithmetic in computed attributes that checks: `/` gives a Float, also on two Ints; Int
# arithmetic within the 64-bit range stays Int, up to its ends.
@present S(FreeSchema) begin
  Thing::Ob
  N::AttrType(Int)
  R::AttrType(Float)
  n::Attr(Thing, N)
  r::Attr(Thing, R)
end
@rule average(a, b) on S begin
  Pre => begin
    (a, b)::Thing
  end
  Keep => begin
    (a, b)::Thing
  end
  Eff => begin
    r(a) == (n(a) + n(b)) / 2
    n(b) == 9223372036854775806 + 1 - n(b)
  end
end
