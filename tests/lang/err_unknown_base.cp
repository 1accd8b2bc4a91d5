@present Sub <: Base begin
  A::Ob
end
