@present Shared(FreeSchema) begin
  X::Ob
end
