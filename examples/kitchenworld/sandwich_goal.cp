# A goal stated in Kitchenworld itself, not migrated from another domain: a sandwich on the
# plate, from the bottom up bread, tomato, lettuce, bread. Each slice is an object in (or on) the
# receptacle of the one below it. Used to judge a transferred plan by what the kitchen wants
# (`catplan transfer ... --goal Sandwich`).

@import "kitchenworld.cp"

@acset_colim Sandwich(KitchenWorld) begin
  (bottom, top)::BreadSliced
  tomato::TomatoSliced
  lettuce::LettuceSliced
  plate::Plate
  (i1, i2, i3, i4)::InReceptacle
  inReceptacle_l(i1) == breadSlicedIsObject(bottom)
  inReceptacle_r(i1) == plateIsReceptacle(plate)
  inReceptacle_l(i2) == tomatoSlicedIsObject(tomato)
  inReceptacle_r(i2) == breadSlicedIsReceptacle(bottom)
  inReceptacle_l(i3) == lettuceSlicedIsObject(lettuce)
  inReceptacle_r(i3) == tomatoSlicedIsReceptacle(tomato)
  inReceptacle_l(i4) == breadSlicedIsObject(top)
  inReceptacle_r(i4) == lettuceSlicedIsReceptacle(lettuce)
end
