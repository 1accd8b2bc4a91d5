(define (domain broken)
  (:requirements :strips)
  (:predicates (p ?x))
  (:action a :parameters (?x ?y) :precondition (p ?x ?y) :effect (not (p ?x))))
