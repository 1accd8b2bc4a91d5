# An unknown object, an unknown generator, an unknown macro.
@present S(FreeSchema) begin
  X::Ob
  f::Hom(X, X)
  g::Hom(X, Y)
end
@acset_colim I(S) begin
  x::X
  f(z) == x
end
@prsent T(FreeSchema) begin
end
