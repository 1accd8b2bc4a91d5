# A small catplan domain that PDDL can express: a relation object (At), a hom-only fact (Door)
# and a Bool attribute (isLit), for `catplan pddl export`.
@present Lights(FreeSchema) begin
  (Room, Robot, At, Door)::Ob
  (door_l, door_r)::Hom(Door, Room)
  robot_of::Hom(At, Robot)
  room_of::Hom(At, Room)
  Lit::AttrType(Bool)
  isLit::Attr(Room, Lit)
end

@domain LightsDomain(Lights) begin
  :move => @migration(Lights, begin
    Pre => @join begin
      robot::Robot
      (from, to)::Room
      d::Door
      door_l(d) == from
      door_r(d) == to
      a::At
      robot_of(a) == robot
      room_of(a) == from
    end
    Keep => @join begin
      robot::Robot
      (from, to)::Room
      d::Door
      door_l(d) == from
      door_r(d) == to
    end
    Eff => @join begin
      robot::Robot
      (from, to)::Room
      d::Door
      door_l(d) == from
      door_r(d) == to
      b::At
      robot_of(b) == robot
      room_of(b) == to
    end
  end)
  :switch_on => @migration(Lights, begin
    Pre => @join begin
      robot::Robot
      room::Room
      a::At
      robot_of(a) == robot
      room_of(a) == room
      isLit(room) == false
    end
    Keep => @join begin
      robot::Robot
      room::Room
      a::At
      robot_of(a) == robot
      room_of(a) == room
    end
    Eff => @join begin
      robot::Robot
      room::Room
      a::At
      robot_of(a) == robot
      room_of(a) == room
      isLit(room) == true
    end
  end)
end

@acset_colim LightsInitial(Lights) begin
  r1::Robot
  (kitchen, hall)::Room
  (d1, d2)::Door
  door_l(d1) == hall; door_r(d1) == kitchen
  door_l(d2) == kitchen; door_r(d2) == hall
  a0::At
  robot_of(a0) == r1; room_of(a0) == hall
  isLit(kitchen) == false; isLit(hall) == false
end

@acset_colim LightsGoal(Lights) begin
  kitchen::Room
  isLit(kitchen) == true
end

@problem LightsProblem(LightsDomain) begin
  initial = LightsInitial
  goal = LightsGoal
end

# A renamed ontology for the same world, and the map that migrates LightsDomain into it: exported
# with `catplan pddl export tests/pddl/lights.cp --problem LightsProblem --map LightsToRooms`.
@present Rooms(FreeSchema) begin
  (Place, Bot, Located, Passage)::Ob
  (pass_from, pass_to)::Hom(Passage, Place)
  located_bot::Hom(Located, Bot)
  located_place::Hom(Located, Place)
  Bright::AttrType(Bool)
  bright::Attr(Place, Bright)
end

@migration LightsToRooms(Rooms, Lights) begin
  Place => Room
  Bot => Robot
  Located => At
  Passage => Door
  pass_from => door_l
  pass_to => door_r
  located_bot => robot_of
  located_place => room_of
  Bright => Lit
  bright => isLit
end
