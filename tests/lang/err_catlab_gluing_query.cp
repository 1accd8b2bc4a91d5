@import catlab

M = @migration SchReflexiveGraph SchGraph begin
  V => V
  E => @cases begin e::E; v::V end
  src => begin e => src; v => id(V) end
  tgt => begin e => tgt; v => id(V) end
  refl => v
end

C = @migration SchGraph begin
  V => V
  Component => @glue begin
    e::E; v::V
    (e → v)::src
  end
  (component: V → Component) => v
end
