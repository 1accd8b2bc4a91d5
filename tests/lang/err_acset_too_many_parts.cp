# Counts in @acset are checked against the limit (10,000,000 parts and variables in all) before
# anything is allocated: 2^32 parts used to trip an assertion, 3e9 variables to run out of memory.
@present G(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  W::AttrType(Int)
  w::Attr(V, W)
end
@acset Huge(G) begin
  V = 4294967296
  E = 0
  W = 3000000000
end
# Each count is within the limit, their sum is not: the count that crosses it is reported.
@acset Sum(G) begin
  V = 6000000
  E = 4000000
  W = 1
end
