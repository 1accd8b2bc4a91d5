# SandwichKitchen: a specific kitchen domain with its own actions, the source of the patterns
# "specific to abstract" (../kitchen_to_colorblocks) and "specific to abstract to specific"
# (../kitchen_to_warehouse).
#
# It differs from the paper's Kitchenworld in one design choice the paper discusses (§VI.B): a
# receptacle is an Object too (inReceptacle_r ends at Object), so one Object part stands for a
# slice whatever it is used as. That is what lets a map send every kitchen thing to a Block.
# Ingredients and utensils are typed by is-a homs into Object, and carry their own attributes.
#
#   catplan validate examples/sandwich_kitchen/sandwich_kitchen.cp --problem MakeSandwich \
#       --plan examples/sandwich_kitchen/sandwich.plan

@present SandwichKitchen(FreeSchema) begin
  # Parent types
  Object::Ob
  Empty::Ob
  Gripper::Ob

  # Robot
  isHolding::Hom(Gripper, Object)
  isEmpty::Hom(Empty, Object)

  # Relations: inReceptacle_l is in (or on) inReceptacle_r
  InReceptacle::Ob
  inReceptacle_l::Hom(InReceptacle, Object)
  inReceptacle_r::Hom(InReceptacle, Object)

  # Attributes of every object
  Free::AttrType(Bool)
  OnCounter::AttrType(Bool)
  Material::AttrType(String)
  isFree::Attr(Object, Free)
  isOnCounter::Attr(Object, OnCounter)
  hasMaterial::Attr(Object, Material)

  # Ingredients and utensils
  Temperature::AttrType(Float64)
  BreadSliced::Ob
  breadSlicedIsObject::Hom(BreadSliced, Object)
  breadSlicedHasTemperature::Attr(BreadSliced, Temperature)
  TomatoSliced::Ob
  tomatoSlicedIsObject::Hom(TomatoSliced, Object)
  tomatoSlicedHasTemperature::Attr(TomatoSliced, Temperature)
  LettuceSliced::Ob
  lettuceSlicedIsObject::Hom(LettuceSliced, Object)
  lettuceSlicedHasTemperature::Attr(LettuceSliced, Temperature)
  Plate::Ob
  plateIsObject::Hom(Plate, Object)
end

# Five things on the counter, nothing in anything; the gripper holds the "nothing" marker, as
# the hand-empty marker of ColorBlocksworld.
@acset_colim Counter(SandwichKitchen) begin
  gripper::Gripper
  empty::Empty
  isHolding(gripper) == isEmpty(empty)
  (bottom, tomato, lettuce, top, plate)::Object
  (slice1, slice2)::BreadSliced
  breadSlicedIsObject(slice1) == bottom; breadSlicedHasTemperature(slice1) == 21.0
  breadSlicedIsObject(slice2) == top; breadSlicedHasTemperature(slice2) == 21.0
  t::TomatoSliced
  tomatoSlicedIsObject(t) == tomato; tomatoSlicedHasTemperature(t) == 6.0
  l::LettuceSliced
  lettuceSlicedIsObject(l) == lettuce; lettuceSlicedHasTemperature(l) == 4.0
  p::Plate
  plateIsObject(p) == plate
  hasMaterial(bottom) == "bread"; hasMaterial(top) == "bread"
  hasMaterial(tomato) == "tomato"; hasMaterial(lettuce) == "lettuce"
  hasMaterial(plate) == "ceramic"
  isOnCounter(bottom) == true; isFree(bottom) == true
  isOnCounter(tomato) == true; isFree(tomato) == true
  isOnCounter(lettuce) == true; isFree(lettuce) == true
  isOnCounter(top) == true; isFree(top) == true
  isOnCounter(plate) == true; isFree(plate) == true
end

# A sandwich on the plate: bread, tomato, lettuce, bread, from the bottom up.
@acset_colim Sandwich(SandwichKitchen) begin
  (bottom, tomato, lettuce, top, plate)::Object
  (slice1, slice2)::BreadSliced
  breadSlicedIsObject(slice1) == bottom
  breadSlicedIsObject(slice2) == top
  t::TomatoSliced
  tomatoSlicedIsObject(t) == tomato
  l::LettuceSliced
  lettuceSlicedIsObject(l) == lettuce
  p::Plate
  plateIsObject(p) == plate
  (i1, i2, i3, i4)::InReceptacle
  inReceptacle_l(i1) == bottom; inReceptacle_r(i1) == plate
  inReceptacle_l(i2) == tomato; inReceptacle_r(i2) == bottom
  inReceptacle_l(i3) == lettuce; inReceptacle_r(i3) == tomato
  inReceptacle_l(i4) == top; inReceptacle_r(i4) == lettuce
end

@domain KitchenActions(SandwichKitchen) begin
  # pick: the hand is empty and the thing is free and on the counter -> holding it.
  @rule pick(thing) begin
    Pre => begin
      gripper::Gripper
      empty::Empty
      thing::Object
      isHolding(gripper) == isEmpty(empty)
      isFree(thing) == true
      isOnCounter(thing) == true
    end
    Keep => begin
      gripper::Gripper
      thing::Object
    end
    Eff => begin
      isHolding(gripper) == thing
      isOnCounter(thing) == false
    end
  end

  # place: holding the thing -> it is on the counter and free, the hand empty again.
  @rule place(thing) begin
    Pre => begin
      gripper::Gripper
      thing::Object
      isHolding(gripper) == thing
    end
    Keep => begin
      gripper::Gripper
      thing::Object
    end
    Eff => begin
      empty::Empty
      isOnCounter(thing) == true
      isFree(thing) == true
      isHolding(gripper) == isEmpty(empty)
    end
  end

  # put_in: holding the thing and the receptacle is free -> the thing is in the receptacle.
  @rule put_in(thing, receptacle) begin
    Pre => begin
      gripper::Gripper
      (thing, receptacle)::Object
      isHolding(gripper) == thing
      isFree(receptacle) == true
    end
    Keep => begin
      gripper::Gripper
      (thing, receptacle)::Object
    end
    Eff => begin
      empty::Empty
      i::InReceptacle
      inReceptacle_l(i) == thing
      inReceptacle_r(i) == receptacle
      isFree(receptacle) == false
      isHolding(gripper) == isEmpty(empty)
    end
  end

  # take_out: the hand is empty and the thing, free, is in the receptacle -> holding the thing,
  # the receptacle free again.
  @rule take_out(thing, receptacle) begin
    Pre => begin
      gripper::Gripper
      empty::Empty
      (thing, receptacle)::Object
      i::InReceptacle
      inReceptacle_l(i) == thing
      inReceptacle_r(i) == receptacle
      isFree(thing) == true
      isHolding(gripper) == isEmpty(empty)
    end
    Keep => begin
      gripper::Gripper
      (thing, receptacle)::Object
    end
    Eff => begin
      isFree(receptacle) == true
      isHolding(gripper) == thing
    end
  end
end

@problem MakeSandwich(KitchenActions) begin
  initial = Counter
  goal = Sandwich
end
