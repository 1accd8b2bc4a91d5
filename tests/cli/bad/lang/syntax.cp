# A statement may not go on after its end, and a declaration needs its 'end'.
@present S(FreeSchema) begin
  X::Ob )
  f::Hom(X, X
end
