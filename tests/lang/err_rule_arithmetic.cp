# Arithmetic in computed attributes: `/` gives a Float (as in Julia), so it cannot compute an Int
# attribute; Int arithmetic on constants that leaves the 64-bit range, and a division by a
# constant zero, are errors at check time.
@present S(FreeSchema) begin
  Thing::Ob
  N::AttrType(Int)
  R::AttrType(Float)
  n::Attr(Thing, N)
  r::Attr(Thing, R)
end
@rule half(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    n(a) == (n(a) + 1) / 2
  end
end
@rule overflow(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    n(a) == n(a) + (9223372036854775807 + 1)
  end
end
@rule products(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    n(a) == 4611686018427387904 * 2 - n(a)
  end
end
@rule negation(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    n(a) == -(-9223372036854775807 - 1) + n(a)
  end
end
@rule by_zero(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    r(a) == r(a) / 0
  end
end
@rule by_float_zero(a) on S begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    r(a) == r(a) + 1.5 / (2.0 - 2.0)
  end
end
# Pre fixes n(a) to 0, so the divisor is the constant 0.
@rule by_fixed_zero(a) on S begin
  Pre => begin
    a::Thing
    n(a) == 0
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    r(a) == 10.0 / n(a)
  end
end
