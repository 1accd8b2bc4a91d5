@present Graph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Weight::AttrType
  weight::Attr(E, Weight)
end

G = @acset Graph begin
  V = 3
  E = 4
  src = [1, 2, 3, 0]
  tgt = [2, 3, 1, 0]
  Weight = 2
  weight = [AttrVar(1), 2.0, -1e3, AttrVar(2)]
end

@acset Loop(Graph) begin
  V = 1; E = 2
  src = 1; tgt = 1
  weight = 0.5
end
