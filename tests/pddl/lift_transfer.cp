# Plans of the lift domain whose move costs come from a table (lift-domain.pddl) and of the one
# where each kind of lift has one cost (lift-flat-domain.pddl), carried both ways: the actions
# are the same, so each step corresponds, and the target plan costs what the target says.
@import "lift-domain.pddl"
@import "lift-flat-domain.pddl"

@migration ToFlat(liftflat, lift) begin
  object => object
  lift => lift
  slow-lift => slow-lift
  fast-lift => fast-lift
  rider => rider
  level => level
  lift-at => lift-at
  rider-at => rider-at
  inside => inside
  serves => serves
  up => up
end

@migration FromFlat(lift, liftflat) begin
  object => object
  lift => lift
  slow-lift => slow-lift
  fast-lift => fast-lift
  rider => rider
  level => level
  lift-at => lift-at
  rider-at => rider-at
  inside => inside
  serves => serves
  up => up
end
