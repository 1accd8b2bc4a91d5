; A small typed domain for the problem and plan cases: a robot carries balls between rooms.
(define (domain rooms)
  (:requirements :strips :typing)
  (:types room ball)
  (:constants hall - room)
  (:predicates (at ?b - ball ?r - room) (robot-in ?r - room))
  (:action carry
    :parameters (?b - ball ?from ?to - room)
    :precondition (and (at ?b ?from) (robot-in ?from))
    :effect (and (not (at ?b ?from)) (at ?b ?to) (not (robot-in ?from)) (robot-in ?to)))
  (:action move
    :parameters (?from ?to - room)
    :precondition (robot-in ?from)
    :effect (and (not (robot-in ?from)) (robot-in ?to))))
