@import "shared_imported.cp"

@present Shared(FreeSchema) begin
  A::Ob
end
