# The roads domain seen as buses on links (transit-domain.pddl). The functions section says that
# a ride takes as long as the road is: the target problem takes the source problem's values of
# road-length as its values of travel-time, so the target plan costs what the source plan does.
@import "roads-domain.pddl"
@import "transit-domain.pddl"

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
