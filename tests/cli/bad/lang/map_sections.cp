# A map's actions and functions sections with every error each can have: all are reported at once.
@import "../../../pddl/roads-domain.pddl"
@import "../../../pddl/transit-domain.pddl"
@import "../../../pddl/fares-domain.pddl"

@migration ToTransit(transit, roads) begin
  object => object
  stop => city
  bus => truck
  bus-at => at
  link => road
  actions => begin
    fly => ride
    drive => walk
    drive
  end
  functions => begin
    travel-time => road-length
    travel-time => road-length
    speed => road-length
    travel-time => distance
    total-cost => total-cost
    travel-time => 3
  end
end

@migration ToFares(fares, roads) begin
  object => object
  stop => city
  bus => truck
  bus-at => at
  link => road
  functions => begin
    stop-fee => road-length
  end
end

@present Plain(FreeSchema) begin
  Thing::Ob
end

@migration Same(Plain, Plain) begin
  Thing => Thing
  functions => begin
    a => b
  end
end
