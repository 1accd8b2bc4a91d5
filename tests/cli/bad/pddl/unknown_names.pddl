; An unknown variable, constant and type; an unsupported construct.
(define (domain names)
  (:requirements :strips :typing)
  (:types block)
  (:predicates (clear ?x - block) (holding ?x - thing))
  (:action pick
    :parameters (?x - block)
    :precondition (and (clear ?y) (clear table))
    :effect (forall (?z - block) (clear ?z))))
