(define (domain broken)
  (:requirements :strips :conditional-effects)
  (:predicates (p ?x) (q ?x))
  (:action a :parameters (?x) :precondition (p ?x) :effect (when (q ?x) (not (p ?x)))))
