; The blocks world without a gripper: three operators that move a clear block in one step.
(define (domain blocks3)
  (:requirements :strips :typing :equality)
  (:types block)
  (:predicates (on ?x - block ?y - block)
               (on-table ?x - block)
               (clear ?x - block))
  (:action move
    :parameters (?b - block ?from - block ?to - block)
    :precondition (and (on ?b ?from) (clear ?b) (clear ?to) (not (= ?b ?to)) (not (= ?from ?to)))
    :effect (and (on ?b ?to) (clear ?from) (not (on ?b ?from)) (not (clear ?to))))
  (:action move-to-table
    :parameters (?b - block ?from - block)
    :precondition (and (on ?b ?from) (clear ?b))
    :effect (and (on-table ?b) (clear ?from) (not (on ?b ?from))))
  (:action move-from-table
    :parameters (?b - block ?to - block)
    :precondition (and (on-table ?b) (clear ?b) (clear ?to) (not (= ?b ?to)))
    :effect (and (on ?b ?to) (not (on-table ?b)) (not (clear ?to)))))
