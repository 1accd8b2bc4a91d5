@present S(FreeSchema) begin
  X::Ob
  T::AttrType
  U::AttrType(Int)
  t::Attr(X, T)
  u::Attr(X, U)
end

@acset_colim I(S) begin
  (a, b, c)::X
  t(a) == "tab\tquote\"backslash\\"
  t(b) == "naïve → ok"
  u(a) == -1; u(b) == 1_000; u(c) == 0
end
