; Buses riding links between stops, each ride taking the time a problem's table gives: the roads
; domain (roads-domain.pddl) in other words. Written for catplan's tests of transfers that carry
; a problem's function values along a map's functions section (roads_to_transit.cp).
(define (domain transit)
  (:requirements :typing :action-costs)
  (:types stop bus)
  (:predicates (bus-at ?b - bus ?s - stop)
               (link ?from ?to - stop))
  (:functions (total-cost) - number
              (travel-time ?from ?to - stop) - number)
  (:action ride
    :parameters (?b - bus ?from ?to - stop)
    :precondition (and (bus-at ?b ?from) (link ?from ?to))
    :effect (and (not (bus-at ?b ?from)) (bus-at ?b ?to)
                 (increase (total-cost) (travel-time ?from ?to)))))
