@present S(FreeSchema) begin
  A::Ob
  T::AttrType(Colour)
end
