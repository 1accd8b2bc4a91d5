# Names hold letters, digits and '_': an emoji or a symbol is no letter.
@present S(FreeSchema) begin
  (Bread🍞, Price€)::Ob
  Größe::Ob
  λ::Ob
end
