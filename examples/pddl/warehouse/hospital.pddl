; Couriers carry samples between adjacent wards of a hospital.
(define (domain hospital)
  (:requirements :strips :typing)
  (:types ward courier sample)
  (:predicates (courier-in ?c - courier ?w - ward)
               (sample-in ?s - sample ?w - ward)
               (adjacent ?w1 ?w2 - ward)
               (holds ?c - courier ?s - sample)
               (hands-free ?c - courier)
               (biohazard ?s - sample))
  (:action walk
    :parameters (?from ?to - ward ?c - courier)
    :precondition (and (courier-in ?c ?from) (adjacent ?from ?to))
    :effect (and (not (courier-in ?c ?from)) (courier-in ?c ?to)))
  (:action collect
    :parameters (?c - courier ?s - sample ?w - ward)
    :precondition (and (courier-in ?c ?w) (sample-in ?s ?w) (hands-free ?c))
    :effect (and (holds ?c ?s) (not (sample-in ?s ?w)) (not (hands-free ?c))))
  (:action deliver
    :parameters (?w - ward ?c - courier ?s - sample)
    :precondition (and (courier-in ?c ?w) (holds ?c ?s))
    :effect (and (sample-in ?s ?w) (hands-free ?c) (not (holds ?c ?s)))))
