@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
@rule touch(a) on S begin
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
# `grab` is declared nowhere.
@domain D(S) begin
  touch
  grab
end
