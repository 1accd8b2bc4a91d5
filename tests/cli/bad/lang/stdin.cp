# Read from standard input.
@present S(FreeSchema) begin
  X::Ob
  f::Hom(X, Nowhere)
end
