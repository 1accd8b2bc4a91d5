@present S(FreeSchema) begin
  (P, Q)::Ob
  f::Hom(P, Q)
  T::AttrType(String)
  label::Attr(Q, T)
end

@acset_colim I(S) begin
  (p1, p2)::P
  label(f(p1)) == "one"
  label(f(p2)) == "two"
  p1 == p2
end
