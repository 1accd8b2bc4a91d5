; A warehouse in the shape of the IPC's storage: `zone` is listed twice in :types (below object
; and below surface), `in` takes a rack or a box, `(either rack box)`, and the domain has a
; constant, the hall the arms start in. Written for catplan's tests.
(define (domain shelving)
  (:requirements :typing)
  (:types arm surface place zone - object
          bay - place
          rack aisle - zone
          zone box - surface)
  (:constants hall - aisle)
  (:predicates (clear ?r - rack)
               (in ?x - (either rack box) ?p - place)
               (free ?a - arm)
               (holding ?a - arm ?b - box)
               (arm-at ?a - arm ?z - zone)
               (on ?b - box ?r - rack)
               (linked ?z1 ?z2 - zone))
  (:action enter
    :parameters (?a - arm ?r - rack)
    :precondition (and (arm-at ?a hall) (linked hall ?r) (clear ?r))
    :effect (and (not (arm-at ?a hall)) (arm-at ?a ?r) (not (clear ?r))))
  (:action go
    :parameters (?a - arm ?r1 ?r2 - rack)
    :precondition (and (arm-at ?a ?r1) (linked ?r1 ?r2) (clear ?r2))
    :effect (and (not (arm-at ?a ?r1)) (arm-at ?a ?r2) (not (clear ?r2)) (clear ?r1)))
  (:action pick
    :parameters (?a - arm ?b - box ?r - rack ?z - rack ?p - place)
    :precondition (and (linked ?r ?z) (arm-at ?a ?z) (free ?a) (on ?b ?r) (in ?r ?p))
    :effect (and (not (on ?b ?r)) (clear ?r) (not (free ?a)) (holding ?a ?b)
                 (not (in ?b ?p))))
  (:action put
    :parameters (?a - arm ?b - box ?r - rack ?z - rack ?p - place)
    :precondition (and (linked ?r ?z) (arm-at ?a ?z) (holding ?a ?b) (clear ?r) (in ?r ?p))
    :effect (and (not (holding ?a ?b)) (not (clear ?r)) (free ?a) (on ?b ?r) (in ?b ?p))))
