@import "cycle_b_part.cp"

@present CycleA(FreeSchema) begin
  A::Ob
end
