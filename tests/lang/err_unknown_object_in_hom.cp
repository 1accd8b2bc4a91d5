@present S(FreeSchema) begin
  A::Ob
  f::Hom(A, Thing)
end
