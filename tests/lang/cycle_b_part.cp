@import "err_import_cycle.cp"

@present CycleB(FreeSchema) begin
  B::Ob
end
