; Buses that depart and then arrive, paying a link's fare, or that are chartered to any stop in one
; step for a flat 50: a drive of the roads domain (roads-domain.pddl) is repaired here, and the
; cheapest repair is the departure and the arrival, the shortest the charter. Written for catplan's
; tests of repairs that sum the target's costs (roads_to_transit.cp).
(define (domain charters)
  (:requirements :typing :action-costs)
  (:types stop bus)
  (:predicates (bus-at ?b - bus ?s - stop)
               (link ?from ?to - stop)
               (en-route ?b - bus ?to - stop))
  (:functions (total-cost) - number
              (fare ?from ?to - stop) - number)
  (:action charter
    :parameters (?b - bus ?from ?to - stop)
    :precondition (bus-at ?b ?from)
    :effect (and (not (bus-at ?b ?from)) (bus-at ?b ?to) (increase (total-cost) 50)))
  (:action depart
    :parameters (?b - bus ?from ?to - stop)
    :precondition (and (bus-at ?b ?from) (link ?from ?to))
    :effect (and (not (bus-at ?b ?from)) (en-route ?b ?to)
                 (increase (total-cost) (fare ?from ?to))))
  (:action arrive
    :parameters (?b - bus ?to - stop)
    :precondition (en-route ?b ?to)
    :effect (and (not (en-route ?b ?to)) (bus-at ?b ?to) (increase (total-cost) 0))))
