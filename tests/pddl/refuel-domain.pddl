; A cost that reads a constant of the domain: each drive costs the refuelling from where it
; arrives back to the depot, a place no parameter names.
(define (domain fuel-depot)
  (:requirements :typing :action-costs)
  (:types place truck)
  (:constants depot - place)
  (:predicates (at ?t - truck ?p - place) (road ?from ?to - place))
  (:functions (total-cost) - number (refuel ?from ?to - place) - number)
  (:action drive
    :parameters (?t - truck ?from ?to - place)
    :precondition (and (at ?t ?from) (road ?from ?to))
    :effect (and (not (at ?t ?from)) (at ?t ?to)
                 (increase (total-cost) (refuel ?to depot)))))
