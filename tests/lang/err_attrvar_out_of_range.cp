@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Weight::AttrType
  weight::Attr(E, Weight)
end

@acset I(Graph) begin
  V = 2
  E = 2
  Weight = 1
  src = 1
  tgt = 2
  weight = [AttrVar(1), AttrVar(2)]
end
