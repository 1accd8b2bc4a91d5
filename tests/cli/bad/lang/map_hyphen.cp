# A name with a hyphen, bare in a map between schemas that are not PDDL imports: it reads as a
# subtraction, and the error says how to write the name.
@present Roads(FreeSchema) begin
  var"truck-at"::Ob
end

@present Transit(FreeSchema) begin
  var"bus-at"::Ob
end

@migration ToTransit(Transit, Roads) begin
  bus-at => var"truck-at"
end

@migration Unknown(Transit, Roads) begin
  bus-stop => var"truck-at"
end
