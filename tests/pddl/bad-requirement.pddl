(define (domain broken)
  (:requirements :strips :conditional-effects)
  (:predicates (p ?x))
  (:action a :parameters (?x) :precondition (p ?x) :effect (not (p ?x))))
