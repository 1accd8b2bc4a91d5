@import catlab

a = @acset WeightedGraph{Float64, Int64} begin
  V = 1
end

b = @acset WeightedGraph{Vector{Float64}} begin
  V = 1
end

Bad = @migration SchGraph begin
  V => V
  src => tgt
  (tgt: E → V) => src
end
