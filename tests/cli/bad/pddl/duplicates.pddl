; A parameter, a constant and a predicate declared twice.
(define (domain dup)
  (:requirements :strips :typing)
  (:types block)
  (:constants table table - block)
  (:predicates (on ?x ?y - block) (on ?x - block))
  (:action move
    :parameters (?b ?to ?b - block)
    :precondition (on ?b ?to)
    :effect (not (on ?b ?to))))
