@present DDS(FreeSchema) begin
  X::Ob
  next::Hom(X, X)
end

@acset_colim Orbit(DDS) begin
  x::X
end
