# A delta map that forgets what a rule's negative application condition sees: the target has
# things but no holders. discard(t) deletes a thing unless a holder holds it; its migrated NAC
# is Δ_F(N) = Δ_F(L) (the holder is forgotten), so it rejects every match, and the step that is
# valid in the source fails in the target. Appendix A covers DPO rules without application
# conditions, so the transfer must not claim to be valid by construction.

@present Shelves(FreeSchema) begin
  Thing::Ob
  Holder::Ob
  holds::Hom(Holder, Thing)
end

@present Things(FreeSchema) begin
  Thing::Ob
end

@migration ForgetHolders(Things, Shelves) begin
  Thing => Thing
end

@acset_colim Tidy(Shelves) begin
  (t1, t2)::Thing
  h::Holder
  holds(h) == t2
end

@acset_colim OneLeft(Shelves) begin
  t::Thing
end

@domain Discarding(Shelves) begin
  :discard => @migration(Shelves, begin
    Pre => @join begin
      t::Thing
    end
    Keep => @join begin
    end
    Eff => @join begin
    end
    NAC => @join begin
      h::Holder
      holds(h) == t
    end
  end)
end

@problem Clear(Discarding) begin
  initial = Tidy
  goal = OneLeft
end
