# A delta map from a bus network to the roads of roads.cp: a stop is a city, a bus a truck, a
# link a road. The generated drive costs what the source's does, so the transfer carries the
# problem's road lengths by name and says what the target plan costs.
@import "roads.cp"

@present Transit(FreeSchema) begin
  (Stop, Bus, Located, Link)::Ob
  located_bus::Hom(Located, Bus)
  located_stop::Hom(Located, Stop)
  link_from::Hom(Link, Stop)
  link_to::Hom(Link, Stop)
  Name::AttrType(String)
  stop_name::Attr(Stop, Name)
end

@migration TransitToRoads(Transit, Roads) begin
  Stop => City
  Bus => Truck
  Located => At
  Link => Road
  located_bus => at_truck
  located_stop => at_city
  link_from => road_from
  link_to => road_to
  Name => Name
  stop_name => city_name
end

# Buses that are somewhere, with no stops: the map forgets the cities, so a generated drive has
# no `from` and `to` for its cost to read, and the target plan has no cost.
@present Buses(FreeSchema) begin
  (Bus, Located)::Ob
  located_bus::Hom(Located, Bus)
end

@migration BusesToRoads(Buses, Roads) begin
  Bus => Truck
  Located => At
  located_bus => at_truck
end
