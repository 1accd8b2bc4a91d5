# The shuttle domain and problem in catplan's language, for `pddl export`: the actions' constant
# costs are written back (:action-costs).
@import "shuttle-domain.pddl"
@import "shuttle-p01.pddl"
