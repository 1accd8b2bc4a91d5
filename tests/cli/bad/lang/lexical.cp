# Characters outside the language, an unknown escape, an unterminated string.
@present S(FreeSchema) begin
  X::Ob $
  Name::AttrType(String)
  name::Attr(X, Name)
end
@acset_colim I(S) begin
  (x, y)::X
  name(x) == "a\q"
  name(y) == "open
end
