; Trucks carry packages over roads whose lengths the problem's table gives; driving costs the
; road's length, loading and unloading cost 1 (the shape of the IPC's transport, without
; capacities). Written for catplan's benchmarks of searches that sum action costs.
(define (domain transport)
  (:requirements :typing :action-costs)
  (:types location locatable - object
          truck package - locatable)
  (:predicates (road ?from ?to - location)
               (at ?x - locatable ?l - location)
               (in ?p - package ?t - truck))
  (:functions (total-cost) - number
              (road-length ?from ?to - location) - number)
  (:action drive
    :parameters (?t - truck ?from ?to - location)
    :precondition (and (at ?t ?from) (road ?from ?to))
    :effect (and (not (at ?t ?from)) (at ?t ?to)
                 (increase (total-cost) (road-length ?from ?to))))
  (:action pick-up
    :parameters (?t - truck ?l - location ?p - package)
    :precondition (and (at ?t ?l) (at ?p ?l))
    :effect (and (not (at ?p ?l)) (in ?p ?t) (increase (total-cost) 1)))
  (:action drop
    :parameters (?t - truck ?l - location ?p - package)
    :precondition (and (at ?t ?l) (in ?p ?t))
    :effect (and (not (in ?p ?t)) (at ?p ?l) (increase (total-cost) 1))))
