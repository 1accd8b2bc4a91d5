; The lift domain (lift-domain.pddl) with a cost per kind of lift instead of a table: a slow
; lift's move costs 4, a fast one's 7. Written for catplan's tests.
(define (domain liftflat)
  (:requirements :typing :action-costs)
  (:types lift - object
          slow-lift fast-lift - lift
          rider level - object)
  (:predicates (lift-at ?l - lift ?f - level)
               (rider-at ?r - rider ?f - level)
               (inside ?r - rider ?l - lift)
               (serves ?l - lift ?f - level)
               (up ?f1 ?f2 - level))
  (:functions (total-cost) - number)
  (:action slow-up
    :parameters (?l - slow-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f1 ?f2) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) 4)))
  (:action slow-down
    :parameters (?l - slow-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f2 ?f1) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) 4)))
  (:action fast-up
    :parameters (?l - fast-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f1 ?f2) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) 7)))
  (:action fast-down
    :parameters (?l - fast-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f2 ?f1) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) 7)))
  (:action board
    :parameters (?r - rider ?l - lift ?f - level)
    :precondition (and (lift-at ?l ?f) (rider-at ?r ?f))
    :effect (and (not (rider-at ?r ?f)) (inside ?r ?l) (increase (total-cost) 0)))
  (:action leave
    :parameters (?r - rider ?l - lift ?f - level)
    :precondition (and (lift-at ?l ?f) (inside ?r ?l))
    :effect (and (not (inside ?r ?l)) (rider-at ?r ?f))))
