# The stacker domain and problem in catplan's language, for `pddl export` and `transfer`: the
# problem's goal asks that the robot hold no block (a negative goal). Same maps the domain to
# itself, so that a plan's transfer checks Δ_F of that goal too.
@import "stacker-domain.pddl"
@import "stacker-p01.pddl"

@migration Same(stacker, stacker) begin
  object => object
  spot => spot
  tier => tier
  robot-at => robot-at
  level => level
  next => next
  adjacent => adjacent
  store => store
  holding => holding
end
