; Declares :adl, as many published domains do, and uses only what catplan reads: typing,
; negative preconditions and equality. catplan names the requirement in a warning and plans.
(define (domain rooms)
  (:requirements :adl)
  (:types room)
  (:predicates (lit ?r - room) (near ?a ?b - room))
  (:action light
    :parameters (?a ?b - room)
    :precondition (and (lit ?a) (near ?a ?b) (not (lit ?b)) (not (= ?a ?b)))
    :effect (lit ?b)))
