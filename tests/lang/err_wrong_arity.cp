@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Weight::AttrType
  weight::Attr(E, Weight)
end

@acset_colim I(Graph) begin
  (v, w)::V
  e::E
  src(e, v) == w
end
