@present S(FreeSchema) begin
  A::Ob
  B::Ob
  A::Ob
end
