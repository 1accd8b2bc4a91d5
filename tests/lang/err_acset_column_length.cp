@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Weight::AttrType
  weight::Attr(E, Weight)
end

@acset I(Graph) begin
  V = 3
  E = 2
  src = [1, 2, 3]
  tgt = [2, 3]
  Weight = 0
  weight = [1.5, 2.5]
end
