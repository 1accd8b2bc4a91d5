# The pipe form of an attribute image takes a constant function or the identity, of a known input.
@present S(FreeSchema) begin
  X::Ob
  Label::AttrType(String)
  label::Attr(X, Label)
  Flag::AttrType(Bool)
end

@present T(FreeSchema) begin
  Y::Ob
  A::AttrType(Bool)
  f::Attr(Y, A)
  g::Attr(Y, A)
  h::Attr(Y, A)
end

@migration M(T, S) begin
  Y => X
  A => Flag
  f => (x |> 3)
  g => (x |> (a -> a == "foo"))
  h => (nothing |> (a -> true))
end
