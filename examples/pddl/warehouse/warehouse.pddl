; Robots carry crates between connected locations of a warehouse; some crates are fragile.
(define (domain warehouse)
  (:requirements :strips :typing)
  (:types location robot crate)
  (:predicates (robot-at ?r - robot ?l - location)
               (crate-at ?c - crate ?l - location)
               (connected ?from ?to - location)
               (carrying ?r - robot ?c - crate)
               (free ?r - robot)
               (fragile ?c - crate))
  (:action move
    :parameters (?r - robot ?from ?to - location)
    :precondition (and (robot-at ?r ?from) (connected ?from ?to))
    :effect (and (robot-at ?r ?to) (not (robot-at ?r ?from))))
  (:action pick
    :parameters (?r - robot ?c - crate ?l - location)
    :precondition (and (robot-at ?r ?l) (crate-at ?c ?l) (free ?r))
    :effect (and (carrying ?r ?c) (not (crate-at ?c ?l)) (not (free ?r))))
  (:action drop
    :parameters (?r - robot ?c - crate ?l - location)
    :precondition (and (robot-at ?r ?l) (carrying ?r ?c))
    :effect (and (crate-at ?c ?l) (free ?r) (not (carrying ?r ?c)))))
