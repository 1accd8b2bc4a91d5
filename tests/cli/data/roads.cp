# A truck on roads whose lengths the problem's table gives: the fewest drives are not the
# cheapest route, and a road the table leaves out (a to e) cannot be driven, since its step has
# no cost.
@present Roads(FreeSchema) begin
  (City, Truck, At, Road)::Ob
  at_truck::Hom(At, Truck)
  at_city::Hom(At, City)
  road_from::Hom(Road, City)
  road_to::Hom(Road, City)
  Name::AttrType(String)
  city_name::Attr(City, Name)
end

@domain Driving(Roads) begin
  facts = (At, Road)
  @rule drive(t, from, to) begin
    cost = length(from, to)
    Pre => begin
      t::Truck
      (from, to)::City
      here::At
      way::Road
      at_truck(here) == t
      at_city(here) == from
      road_from(way) == from
      road_to(way) == to
    end
    Keep => begin
      t::Truck
      (from, to)::City
      way::Road
      road_from(way) == from
      road_to(way) == to
    end
    Eff => begin
      there::At
      at_truck(there) == t
      at_city(there) == to
    end
  end
end

@acset_colim Map(Roads) begin
  (a, b, c, d, e)::City
  city_name(a) == "a"
  city_name(b) == "b"
  city_name(c) == "c"
  city_name(d) == "d"
  city_name(e) == "e"
  t1::Truck
  start::At
  at_truck(start) == t1
  at_city(start) == a
  (ad, ab, bc, cd, ae, ed)::Road
  road_from(ad) == a
  road_to(ad) == d
  road_from(ab) == a
  road_to(ab) == b
  road_from(bc) == b
  road_to(bc) == c
  road_from(cd) == c
  road_to(cd) == d
  road_from(ae) == a
  road_to(ae) == e
  road_from(ed) == e
  road_to(ed) == d
end

@acset_colim AtD(Roads) begin
  t1::Truck
  d::City
  city_name(d) == "d"
  goal::At
  at_truck(goal) == t1
  at_city(goal) == d
end

# toll is read by no rule's cost: a warning, and pddl export leaves the value out.
@problem ToD(Driving) begin
  initial = Map
  goal = AtD
  toll(a) = 2
  length(a, d) = 20
  length(a, b) = 3
  length(b, c) = 4
  length(c, d) = 5
  length(e, d) = 1
end

# The same, measured by steps.
@problem ToDInSteps(Driving) begin
  initial = Map
  goal = AtD
  metric = steps
end
