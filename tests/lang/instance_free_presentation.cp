# The free instance: fresh parts for undefined homs, fresh variables for undefined
# attributes, congruence closure, named variables, attribute equality.
@present S(FreeSchema) begin
  (P, Q, R)::Ob
  f::Hom(P, Q)
  g::Hom(Q, R)
  Name::AttrType
  name::Attr(R, Name)
  Size::AttrType
  size::Attr(Q, Size)
end

Inst = @acset_colim yS begin
  (p1, p2, p3)::P
  n::Name
  q::Q
  f(p1) == q
  p2 == p3
  name(g(f(p1))) == n
  name(g(f(p2))) == "second"
  size(f(p1)) == size(f(p2))
  size(q) == 2
  size(f(p2)) == 2.0
end

# Generators may be declared after use, and a literal may settle a kind before the schema's text.
@acset_colim Late(S) begin
  r::R
  name(r) == alias
  alias::Name
end
