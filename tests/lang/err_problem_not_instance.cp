@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
@acset_colim Start(S) begin
  t::Thing
end
@domain D(S) begin
  @rule touch(a) begin
    Pre => begin
      a::Thing
    end
  end
end
# The goal names the domain and the initial state names the schema: neither is an instance.
@problem P(D) begin
  initial = S
  goal = D
end
