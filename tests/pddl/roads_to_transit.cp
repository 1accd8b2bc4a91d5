# The roads domain seen as buses on links (transit-domain.pddl). The functions section says that
# a ride takes as long as the road is: the target problem takes the source problem's values of
# road-length as its values of travel-time, so the target plan costs what the source plan does.
# ToHops and ToCharters carry the same plans into domains where each drive is repaired; ToFares,
# at the end, names a function whose arguments the source's values cannot fill.
@import "roads-domain.pddl"
@import "transit-domain.pddl"
@import "hops-domain.pddl"
@import "fares-domain.pddl"
@import "charters-domain.pddl"

@migration ToTransit(transit, roads) begin
  object => object
  stop => city
  bus => truck
  bus-at => at
  link => road
  functions => begin
    travel-time => road-length
  end
end

# The same map without the functions section: the target problem has no travel times.
@migration ToTransitWithoutTimes(transit, roads) begin
  object => object
  stop => city
  bus => truck
  bus-at => at
  link => road
end

# Roads seen as buses that depart and arrive (hops-domain.pddl): every drive is repaired into a
# departure and an arrival. The fares are the road lengths; the shuttle's fares are carried from
# nothing, so the repairs, which read the target's costs, never take a shuttle.
@migration ToHops(hops, roads) begin
  object => object
  stop => city
  bus => truck
  bus-at => at
  link => road
  en-route => @empty
  functions => begin
    fare => road-length
  end
end

# Roads seen as buses that depart and arrive, or are chartered (charters-domain.pddl): a charter
# reaches the next stop in one step for 50, a departure and an arrival for the road's length. The
# repairs sum the fares the functions section carries, so each drive becomes the cheaper two.
@migration ToCharters(charters, roads) begin
  object => object
  stop => city
  bus => truck
  bus-at => at
  link => road
  en-route => @empty
  functions => begin
    fare => road-length
  end
end

# Fares are set per bus and stop (fares-domain.pddl), and a road's length is between two cities:
# no value of road-length is a fare, since its first argument is a stop, not a bus. The transfer
# names the values it leaves out, and the target plan has no cost.
@migration ToFares(fares, roads) begin
  object => object
  stop => city
  bus => truck
  bus-at => at
  link => road
  functions => begin
    fare => road-length
  end
end
