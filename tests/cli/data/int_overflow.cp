# A counter one below the largest Int: the second increment overflows, which makes the step
# invalid (Int arithmetic is checked, never wrapped).
@present Counter(FreeSchema) begin
  Thing::Ob
  N::AttrType(Int)
  n::Attr(Thing, N)
end
@acset_colim Start(Counter) begin
  t::Thing
  n(t) == 9223372036854775806
end
@acset_colim Done(Counter) begin
  t::Thing
  n(t) == 9223372036854775807
end
@rule inc(a) on Counter begin
  Pre => begin
    a::Thing
  end
  Keep => begin
    a::Thing
  end
  Eff => begin
    n(a) == n(a) + 1
  end
end
@domain Counting(Counter) begin
  inc
end
@problem Overflow(Counting) begin
  initial = Start
  goal = Done
end
