; PDDL semantics the DPO encoding must keep: a fact added while true stays one fact; parameters
; may bind the same object unless (not (= ..)) forbids it; negative preconditions; nullary facts.
(define (domain dup)
  (:requirements :strips :negative-preconditions :equality)
  (:predicates (mark ?x) (link ?x ?y) (done))
  (:action set-mark
    :parameters (?x)
    :precondition ()
    :effect (mark ?x))
  (:action clear-mark
    :parameters (?x)
    :precondition (mark ?x)
    :effect (not (mark ?x)))
  (:action connect
    :parameters (?x ?y)
    :precondition (not (link ?x ?y))
    :effect (link ?x ?y))
  (:action connect-other
    :parameters (?x ?y)
    :precondition (not (= ?x ?y))
    :effect (and (link ?x ?y) (done))))
