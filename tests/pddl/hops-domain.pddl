; Buses that depart and then arrive: a drive of the roads domain (roads-domain.pddl) is two steps
; here, so each is repaired. A shuttle departs as a bus does, but its fares are a table no map
; carries, so a problem carried from roads gives it no cost: a repair must not take it.
; Written for catplan's tests of repairs that read the target's costs (roads_to_transit.cp).
(define (domain hops)
  (:requirements :typing :action-costs)
  (:types stop bus)
  (:predicates (bus-at ?b - bus ?s - stop)
               (link ?from ?to - stop)
               (en-route ?b - bus ?to - stop))
  (:functions (total-cost) - number
              (shuttle-fare ?from ?to - stop) - number
              (fare ?from ?to - stop) - number)
  (:action shuttle
    :parameters (?b - bus ?from ?to - stop)
    :precondition (and (bus-at ?b ?from) (link ?from ?to))
    :effect (and (not (bus-at ?b ?from)) (en-route ?b ?to)
                 (increase (total-cost) (shuttle-fare ?from ?to))))
  (:action depart
    :parameters (?b - bus ?from ?to - stop)
    :precondition (and (bus-at ?b ?from) (link ?from ?to))
    :effect (and (not (bus-at ?b ?from)) (en-route ?b ?to)
                 (increase (total-cost) (fare ?from ?to))))
  (:action arrive
    :parameters (?b - bus ?to - stop)
    :precondition (en-route ?b ?to)
    :effect (and (not (en-route ?b ?to)) (bus-at ?b ?to) (increase (total-cost) 0))))
