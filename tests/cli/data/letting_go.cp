# A problem with a negative goal: some thing that nothing holds.
@present Hand(FreeSchema) begin
  (Thing, Held)::Ob
  held::Hom(Held, Thing)
end

@acset_colim Holding(Hand) begin
  t::Thing
  h::Held
  held(h) == t
end

@acset_colim Something(Hand) begin
  t::Thing
end

@domain Letting(Hand) begin
  facts = Held
  @rule let_go(a) begin
    cost = 2
    Pre => begin
      a::Thing
      h::Held
      held(h) == a
    end
    Keep => begin
      a::Thing
    end
  end
end

@problem Free(Letting) begin
  initial = Holding
  goal = Something
  NAC => begin
    h::Held
    held(h) == t
  end
end
