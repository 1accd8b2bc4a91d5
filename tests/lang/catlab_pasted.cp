# A Catlab notebook pasted as it is: Julia lines are skipped, `using Catlab` brings Catlab's
# schemas, @acset_type names a schema again, type parameters give kinds.
module Notebook
using Catlab, Catlab.Graphs
import JSON
draw(g) = to_graphviz(g, node_labels=true)
function add_loops!(g)
  for v in parts(g, :V)
    add_edge!(g, v, v)
  end
  return g
end

@present SchCycle <: SchDDS begin
  cycle2 := Φ ⋅ Φ == id(X)
end

@present SchPath <: SchWeightedGraph begin
  Weight::AttrType(Float)
end
@acset_type WeightedPath(SchPath, index=[:src, :tgt]) <: AbstractGraph

p = @acset WeightedPath begin
  V = 2; E = 1
  src = [1]; tgt = [2]
  weight = [0.5]
end

w = @acset Catlab.Graphs.WeightedGraph{Float64} begin
  V = 2; E = 1
  src = [1]; tgt = [2]
  weight = [2.0]
end

named = @acset NamedGraph{Symbol, Symbol} begin
  V = 2; E = 1
  src = [1]; tgt = [2]
  vname = [:a, :b]
  ename = [:f]
end

Rev = @migration SchGraph begin
  V => V
  E => E
  (src: E → V) => tgt
  (tgt: E → V) => src
end
G = Graph(3)
end
