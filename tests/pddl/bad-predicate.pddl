(define (domain broken)
  (:requirements :strips)
  (:predicates (p ?x))
  (:action a :parameters (?x) :precondition (q ?x) :effect (not (p ?x))))
