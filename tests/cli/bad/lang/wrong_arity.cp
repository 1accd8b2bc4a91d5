# A hom takes one argument.
@present S(FreeSchema) begin
  (X, Y)::Ob
  f::Hom(X, Y)
end
@acset_colim I(S) begin
  x::X
  y::Y
  f(x, x) == y
end
