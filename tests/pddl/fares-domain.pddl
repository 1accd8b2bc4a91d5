; Buses that pay a fare for each stop they ride to, set per bus, and a fee at each stop: the
; roads domain (roads-domain.pddl) again, with functions whose arguments a road's length cannot
; fill. Written for catplan's tests of the checks of a map's functions section
; (roads_to_transit.cp, tests/cli/bad/lang/map_sections.cp).
(define (domain fares)
  (:requirements :typing :action-costs)
  (:types stop bus)
  (:predicates (bus-at ?b - bus ?s - stop)
               (link ?from ?to - stop))
  (:functions (total-cost) - number
              (fare ?b - bus ?to - stop) - number
              (stop-fee ?s - stop) - number)
  (:action ride
    :parameters (?b - bus ?from ?to - stop)
    :precondition (and (bus-at ?b ?from) (link ?from ?to))
    :effect (and (not (bus-at ?b ?from)) (bus-at ?b ?to)
                 (increase (total-cost) (fare ?b ?to)))))
