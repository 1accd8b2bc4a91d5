@present S(FreeSchema) begin
  (A, B, C)::Ob
  f::Hom(A, B)
  g::Hom(C, A)
  f ⋅ g == f
end
