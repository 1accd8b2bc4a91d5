@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Weight::AttrType
  weight::Attr(E, Weight)
end

@present Graph(FreeSchema) begin
  X::Ob
end
