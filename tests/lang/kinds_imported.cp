# A schema whose attribute type declares no value kind (imported by another case).
@present Weighed(FreeSchema) begin
  Thing::Ob
  Mass::AttrType
  hasMass::Attr(Thing, Mass)
end
