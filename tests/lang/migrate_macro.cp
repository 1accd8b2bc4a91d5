# DataMigrations' @migrate (reference §5.5 (a) and (d)): a map written and run at once.

@present SchSet(FreeSchema) begin
  X::Ob
end

@present SchGraph(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
end

@acset FiveSet(SchSet) begin
  X = 5
end

# One vertex, an edge per element, all loops: src and tgt into @unit need no entry.
Bouquet = @migrate SchGraph FiveSet begin
  V => @unit
  E => X
end

# Five vertices, no edges.
Discrete = @migrate SchGraph FiveSet begin
  V => X
  E => @empty
end

@acset Path5(SchGraph) begin
  V = 5
  E = 4
  src = [1, 2, 3, 4]
  tgt = [2, 3, 4, 5]
end

# Edges are the paths of length two: (1,3), (2,4), (3,5).
@migrate TwoPaths(SchGraph, Path5) begin
  V => V
  E => @join begin
    v::V
    (e1, e2)::E
    tgt(e1) == v
    src(e2) == v
  end
  src => e1 ⋅ src
  tgt => e2 ⋅ tgt
end
