# A parameter names one part of Pre; naming it twice (in a rule's header or where a domain names
# a rule) is an error.
@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
end
@rule grab(h, a, h) on S begin
  Pre => begin
    h::Holder
    a::Thing
    holds(h) == a
  end
end
@rule touch(a, b) on S begin
  Pre => begin
    (a, b)::Thing
  end
end
@domain D(S) begin
  touch(b, b)
end
