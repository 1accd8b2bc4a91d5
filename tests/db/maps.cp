# Maps whose migration inside a database is compared with catplan's own (src/catplan/db tests):
# delta and conjunctive, with paths, filters, value variables, constants and @empty.

@present LabelledGraph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Label::AttrType(String)
  Weight::AttrType(Float)
  Count::AttrType(Int)
  label::Attr(V, Label)
  weight::Attr(E, Weight)
  count::Attr(E, Count)
end

@present Graph2(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Label::AttrType(String)
  Weight::AttrType(Float)
  label::Attr(V, Label)
  weight::Attr(E, Weight)
  srcLabel::Attr(E, Label)
end

@present Marked(FreeSchema) begin
  (V, E, Mark)::Ob
  (src, tgt)::Hom(E, V)
  marked::Hom(Mark, V)
  Label::AttrType(String)
  Flag::AttrType(Bool)
  name::Attr(Mark, Label)
  flag::Attr(Mark, Flag)
end

# Delta: the edges reversed, the labels read along paths.
@migration Reverse(Graph2, LabelledGraph) begin
  V => V
  E => E
  src => tgt
  tgt => src
  Label => Label
  Weight => Weight
  label => label
  weight => weight
  srcLabel => tgt ⋅ label
end

# Conjunctive: the edges are the paths of length two.
@migration TwoPaths(Graph2, LabelledGraph) begin
  V => V
  E => @join begin
    v::V
    (e1, e2)::E
    tgt(e1) == v
    src(e2) == v
  end
  src => e1 ⋅ src
  tgt => e2 ⋅ tgt
  Label => Label
  Weight => Weight
  label => label
  weight => e1 ⋅ weight
  srcLabel => v ⋅ label
end

# Conjunctive with a value variable: an edge between any two vertices with the same label,
# the value node first (so the order is by label, then by vertices).
@migration SameLabel(Graph2, LabelledGraph) begin
  V => V
  E => @join begin
    L::Label
    (a, b)::V
    (la:a → L)::label
    (lb:b → L)::label
  end
  src => a
  tgt => b
  Label => Label
  Weight => Weight
  label => label
  weight => (x -> 1.5)
  srcLabel => L
end

# Filters: the red vertices, the edges between red vertices, marks of red vertices.
@migration RedPart(Marked, LabelledGraph) begin
  V => @join begin
    v::V
    C::Label
    (lv:v → C)::label
    (red:v → C)::(v -> "red")
  end
  E => @join begin
    e::E
    (s, t)::V
    C::Label
    src(e) == s
    tgt(e) == t
    (ls:s → C)::label
    (lt:t → C)::label
    (red:s → C)::(s -> "red")
  end
  Mark => @join begin
    e::E
    v::V
    C::Label
    src(e) == v
    (lv:v → C)::label
    (red:v → C)::(v -> "red")
  end
  src => (v => s; C => C)
  tgt => (v => t; C => C)
  marked => (v => v; C => C)
  Label => Label
  name => C
  Flag => Bool
  flag => (x -> true)
end

# Nothing but the vertices, as edges of an empty graph.
@migration Discrete(Graph2, LabelledGraph) begin
  V => V
  E => @empty
  Label => Label
  Weight => Weight
  label => label
end
