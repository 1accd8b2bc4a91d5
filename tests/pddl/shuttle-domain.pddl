; Shuttles between cities in the shape of the IPC's zenotravel (STRIPS, untyped): objects are
; told apart by unary predicates, written as some IPC files write them, without a space
; between a name and a variable (person?p). Flying costs 3 and boarding 1 (:action-costs).
; Written for catplan's tests.
(define (domain shuttle)
  (:requirements :strips :action-costs)
  (:predicates (person ?p) (shuttle ?s) (city ?c)
               (at ?x ?c) (in ?p ?s))
  (:functions (total-cost) - number)
  (:action board
    :parameters (?p ?s ?c)
    :precondition (and (person?p) (shuttle?s) (city?c) (at ?p?c) (at ?s ?c))
    :effect (and (not (at ?p ?c)) (in ?p ?s) (increase (total-cost) 1)))
  (:action debark
    :parameters (?p ?s ?c)
    :precondition (and (person ?p) (shuttle ?s) (city ?c) (in ?p ?s) (at ?s ?c))
    :effect (and (not (in ?p ?s)) (at ?p ?c) (increase (total-cost) 1)))
  (:action fly
    :parameters (?s ?from ?to)
    :precondition (and (shuttle ?s) (city?from) (city ?to) (at ?s ?from))
    :effect (and (not (at ?s ?from)) (at ?s ?to) (increase (total-cost) 3))))
