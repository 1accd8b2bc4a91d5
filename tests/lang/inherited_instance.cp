@present Base(FreeSchema) begin
  A::Ob
  C::AttrType(Bool)
  c::Attr(A, C)
end

@present Sub <: Base begin
  B::Ob
  f::Hom(B, A)
end

@acset_colim I(Sub) begin
  b::B
  c(f(b)) == true
end
