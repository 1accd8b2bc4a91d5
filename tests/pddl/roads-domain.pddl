; A truck on roads whose lengths a problem's table gives: the fewest drives are not the cheapest
; route, and a road the table leaves out cannot be driven (its cost has no value). Written for
; catplan's tests of searches that sum action costs.
(define (domain roads)
  (:requirements :typing :action-costs)
  (:types city truck)
  (:predicates (at ?t - truck ?c - city)
               (road ?from ?to - city))
  (:functions (total-cost) - number
              (road-length ?from ?to - city) - number)
  (:action drive
    :parameters (?t - truck ?from ?to - city)
    :precondition (and (at ?t ?from) (road ?from ?to))
    :effect (and (not (at ?t ?from)) (at ?t ?to)
                 (increase (total-cost) (road-length ?from ?to)))))
