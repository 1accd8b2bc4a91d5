@present S(FreeSchema) begin
  A::Ob
  f::Hom(A, A) extra
  g::Hom(A A)
end
