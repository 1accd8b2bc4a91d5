# @migrate takes an instance to migrate, and a map whose entries are checked as any map's.

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

Unknown = @migrate SchGraph Nothing begin
  V => X
  E => X
end

NotAnInstance = @migrate SchGraph SchSet begin
  V => X
  E => X
end

Unmapped = @migrate SchGraph FiveSet begin
  V => X
  E => X
end
