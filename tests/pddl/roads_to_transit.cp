# The roads domain seen as buses on links (transit-domain.pddl). The functions section says that
# a ride takes as long as the road is: the target problem takes the source problem's values of
# road-length as its values of travel-time, so the target plan costs what the source plan does.
# ToHops, at the end, carries the same plans into a domain where each drive is repaired.
@import "roads-domain.pddl"
@import "transit-domain.pddl"
@import "hops-domain.pddl"

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
