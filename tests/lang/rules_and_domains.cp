@present S(FreeSchema) begin
  (Thing, Holder)::Ob
  holds::Hom(Holder, Thing)
  Flag::AttrType(Bool)
  Size::AttrType(Int)
  flag::Attr(Thing, Flag)
  size::Attr(Thing, Size)
end
@acset_colim Start(S) begin
  (t, u)::Thing
  flag(t) == false
  size(u) == 2
end
@acset_colim Done(S) begin
  t::Thing
  flag(t) == true
end

# Our form at top level: explicit parameters, a negative application condition (no holder may
# hold a) and a computed attribute.
@rule mark(a) on S begin
  Pre => @join begin
    a::Thing
    flag(a) == false
  end
  Keep => @join begin
    a::Thing
  end
  Eff => @join begin
    a::Thing
    flag(a) == true
    size(a) == size(a) + 1
  end
  NAC => begin
    h::Holder
    holds(h) == a
  end
end

# The slide form: L, K, R and the maps l and r from K's names to L's and R's.
drop = @migration SchRule S begin
  L => @join begin
    h::Holder
    t::Thing
    holds(h) == t
  end
  K => @join begin
    t::Thing
  end
  R => @join begin
    t::Thing
  end
  l => begin
    t => t
  end
  r => begin
    t => t
  end
end

@domain Marking(S) begin
  mark
  drop(t)
  # The paper's form, pasted: `:name => @migration(Schema, begin ... end)`.
  :hold => @migration(S, begin
    Pre => @join begin
      t::Thing
    end
    Keep => @join begin
      t::Thing
    end
    Eff => @join begin
      t::Thing
      h::Holder
      holds(h) == t
    end
  end)
  # Our form inside a domain: the schema is the domain's.
  @rule forget(a) begin
    Pre => begin
      a::Thing
    end
  end
end

@problem MarkOne(Marking) begin
  initial = Start
  goal = Done
end
