@present S(FreeSchema) begin
  (A, B, C)::Ob
  f::Hom(A, B)
  g::Hom(B, C)
  h::Hom(A, B)
  compose(f, g) == h
end
