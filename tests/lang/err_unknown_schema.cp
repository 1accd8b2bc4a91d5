@acset_colim I(Grahp) begin
  v::V
end
