@present S(FreeSchema) begin
  A::Ob
  B::Ob $
end
