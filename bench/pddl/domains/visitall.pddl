; Visitall (IPC 2011), written for catplan's benchmarks: a robot on a grid visits every cell.
(define (domain visitall)
  (:requirements :strips :typing)
  (:types place)
  (:predicates (connected ?x - place ?y - place)
               (at-robot ?x - place)
               (visited ?x - place))
  (:action move
    :parameters (?from - place ?to - place)
    :precondition (and (at-robot ?from) (connected ?from ?to))
    :effect (and (at-robot ?to) (not (at-robot ?from)) (visited ?to))))
