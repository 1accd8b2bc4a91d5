#= Every schema form: tuples, declared and inferred kinds, inheritance,
   equations written three ways. =#
@present Base(FreeSchema) begin
  (V, E)::Ob
  (src, tgt)::Hom(E, V)
  Label::AttrType(Symbol)
end

@present Reflexive <: Base begin
  refl::Hom(V, E)
  compose(refl, src) == id(V)
  refl ⋅ tgt == id(V)
  refl · src == refl . tgt
  Weight::AttrType(Float64)
  (count, n)::AttrType(Int)
  label::Attr(V, Label)
  weight::Attr(E, Weight)
end

@present Multi <: (Base, Reflexive) begin
  Cafe::Ob
  dü::Hom(Cafe, V)
end
