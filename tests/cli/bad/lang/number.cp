# Numbers must fit: a Float is finite and does not underflow to 0, an Int fits in 64 bits.
@present S(FreeSchema) begin
  X::Ob
  (F, I)::AttrType
  f::Attr(X, F)
  i::Attr(X, I)
end
@acset_colim A(S) begin
  (x, y)::X
  f(x) == 1e999
  f(y) == 1e-999
  i(x) == 99999999999999999999
end
