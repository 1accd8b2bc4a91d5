; A building robot in the shape of the IPC's termes: it walks between spots of equal height,
; raises a spot by placing the block it holds, lowers one by taking a block, and fetches or
; returns blocks at a store. Goals say which spots stand how high and that the robot holds no
; block, a negative goal. Written for catplan's tests.
(define (domain stacker)
  (:requirements :typing :negative-preconditions)
  (:types spot tier)
  (:predicates (robot-at ?s - spot)
               (level ?s - spot ?t - tier)
               (next ?t1 ?t2 - tier)
               (adjacent ?s1 ?s2 - spot)
               (store ?s - spot)
               (holding))
  (:action move
    :parameters (?from ?to - spot ?t - tier)
    :precondition (and (robot-at ?from) (adjacent ?from ?to) (level ?from ?t) (level ?to ?t))
    :effect (and (not (robot-at ?from)) (robot-at ?to)))
  (:action place
    :parameters (?r ?s - spot ?t1 ?t2 - tier)
    :precondition (and (robot-at ?r) (adjacent ?r ?s) (level ?r ?t1) (level ?s ?t1)
                       (next ?t1 ?t2) (holding) (not (store ?s)))
    :effect (and (not (level ?s ?t1)) (level ?s ?t2) (not (holding))))
  (:action take
    :parameters (?r ?s - spot ?t1 ?t2 - tier)
    :precondition (and (robot-at ?r) (adjacent ?r ?s) (level ?r ?t1) (level ?s ?t2)
                       (next ?t1 ?t2) (not (holding)) (not (store ?s)))
    :effect (and (not (level ?s ?t2)) (level ?s ?t1) (holding)))
  (:action fetch
    :parameters (?r ?s - spot)
    :precondition (and (robot-at ?r) (adjacent ?r ?s) (store ?s) (not (holding)))
    :effect (holding))
  (:action give-back
    :parameters (?r ?s - spot)
    :precondition (and (robot-at ?r) (adjacent ?r ?s) (store ?s) (holding))
    :effect (not (holding))))
