# A conjunctive map whose migration does not preserve a pushout: crates in a store are labelled
# "medicine" or "linen"; the target sees two kinds of supplies, Medicine and Linen, each the
# crates of one label. relabel(c) sets a crate's label without testing the old one, so in the
# source a linen crate becomes a medicine crate, while in the target Δ_F(relabel) matches the
# crate as neither kind (its Pre sees no label) and cannot move it from Linen to Medicine: the
# target keeps a stale Linen part. relabel_linen tests the old label: its migration deletes the
# Linen part and creates a Medicine one, and the target follows the source.

@present Store(FreeSchema) begin
  Crate::Ob
  Label::AttrType(String)
  label::Attr(Crate, Label)
end

@present Supplies(FreeSchema) begin
  Medicine::Ob
  Linen::Ob
end

@migration Sorted(Supplies, Store) begin
  Medicine => @join begin
    c::Crate
    label(c) == "medicine"
  end
  Linen => @join begin
    c::Crate
    label(c) == "linen"
  end
end

@acset_colim Shelf(Store) begin
  (m1, m2, l1)::Crate
  label(m1) == "medicine"
  label(m2) == "medicine"
  label(l1) == "linen"
end

@acset_colim ThreeMedicines(Store) begin
  (a, b, c)::Crate
  label(a) == "medicine"
  label(b) == "medicine"
  label(c) == "medicine"
end

# The goal intended in the target: three medicines (a goal cannot say "no linen").
@acset_colim Stocked(Supplies) begin
  (a, b, c)::Medicine
end

@domain Relabelling(Store) begin
  :relabel => @migration(Store, begin
    Pre => @join begin
      c::Crate
    end
    Keep => @join begin
      c::Crate
    end
    Eff => @join begin
      c::Crate
      label(c) == "medicine"
    end
  end)

  :relabel_linen => @migration(Store, begin
    Pre => @join begin
      c::Crate
      label(c) == "linen"
    end
    Keep => @join begin
      c::Crate
    end
    Eff => @join begin
      c::Crate
      label(c) == "medicine"
    end
  end)
end

@problem Restock(Relabelling) begin
  initial = Shelf
  goal = ThreeMedicines
end
