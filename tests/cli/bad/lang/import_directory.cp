# A directory is no file to import.
@import "."
@present S(FreeSchema) begin
  X::Ob
end
