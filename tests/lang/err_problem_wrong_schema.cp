@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
@present Other(FreeSchema) begin
  Thing::Ob
end
@acset_colim Start(S) begin
  t::Thing
end
@acset_colim Elsewhere(Other) begin
  t::Thing
end
@domain D(S) begin
  @rule touch(a) begin
    Pre => begin
      a::Thing
    end
    Keep => begin
      a::Thing
    end
    Eff => begin
      a::Thing
      flag(a) == true
    end
  end
end
# The goal is a state of another schema.
@problem P(D) begin
  initial = Start
  goal = Elsewhere
end
