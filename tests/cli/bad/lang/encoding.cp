# A byte that is not UTF-8 (0xFF) in a name and one (0xC0) in a string.
@present S(FreeSchema) begin
  Xÿ::Ob
  L::AttrType(String)
  l::Attr(X, L)
end
@acset_colim I(S) begin
  x::X
  l(x) == "À"
end
