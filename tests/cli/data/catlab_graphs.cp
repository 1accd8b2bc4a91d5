# Catlab's schemas, for the JSON import tests: SchReflexiveGraph has the equations
# refl ⋅ src == id(V) and refl ⋅ tgt == id(V).
@import catlab
