; A lift domain in the shape of the IPC's elevators: two kinds of lift, whose moves cost what a
; table of the problem says (travel-slow, travel-fast), and boarding and leaving that cost
; nothing. Written for catplan's tests.
(define (domain lift)
  (:requirements :typing :action-costs)
  (:types lift - object
          slow-lift fast-lift - lift
          rider level - object)
  (:predicates (lift-at ?l - lift ?f - level)
               (rider-at ?r - rider ?f - level)
               (inside ?r - rider ?l - lift)
               (serves ?l - lift ?f - level)
               (up ?f1 ?f2 - level))
  (:functions (total-cost) - number
              (travel-slow ?f1 ?f2 - level) - number
              (travel-fast ?f1 ?f2 - level) - number)
  (:action slow-up
    :parameters (?l - slow-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f1 ?f2) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) (travel-slow ?f1 ?f2))))
  (:action slow-down
    :parameters (?l - slow-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f2 ?f1) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) (travel-slow ?f2 ?f1))))
  (:action fast-up
    :parameters (?l - fast-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f1 ?f2) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) (travel-fast ?f1 ?f2))))
  (:action fast-down
    :parameters (?l - fast-lift ?f1 ?f2 - level)
    :precondition (and (lift-at ?l ?f1) (up ?f2 ?f1) (serves ?l ?f2))
    :effect (and (not (lift-at ?l ?f1)) (lift-at ?l ?f2)
                 (increase (total-cost) (travel-fast ?f2 ?f1))))
  (:action board
    :parameters (?r - rider ?l - lift ?f - level)
    :precondition (and (lift-at ?l ?f) (rider-at ?r ?f))
    :effect (and (not (rider-at ?r ?f)) (inside ?r ?l) (increase (total-cost) 0)))
  (:action leave
    :parameters (?r - rider ?l - lift ?f - level)
    :precondition (and (lift-at ?l ?f) (inside ?r ?l))
    :effect (and (not (inside ?r ?l)) (rider-at ?r ?f))))
