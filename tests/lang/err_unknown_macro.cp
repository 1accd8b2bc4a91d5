@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Weight::AttrType
  weight::Attr(E, Weight)
end

@action swap(Graph) begin
  e::E
end
