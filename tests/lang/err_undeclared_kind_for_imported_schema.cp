@import "shared_imported.cp"
@import "kinds_imported.cp"

@acset_colim K(Weighed) begin
  k::Thing
  hasMass(k) == 0.5
end
