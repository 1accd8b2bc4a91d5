@import "no_such_file.cp"

@present S(FreeSchema) begin
  A::Ob
end
