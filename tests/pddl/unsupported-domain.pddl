; Valid PDDL that catplan does not read: every requirement, section and construct below is
; reported by name, at its place, and the command exits 3 ("valid but unsupported").
(define (domain trucking)
  (:requirements :typing :conditional-effects :derived-predicates :numeric-fluents
                 :durative-actions :disjunctive-preconditions :universal-preconditions)
  (:types truck place)
  (:predicates (at ?t - truck ?p - place) (road ?a ?b - place) (busy ?t - truck)
               (reachable ?a ?b - place))
  (:functions (fuel ?t - truck) - number)
  (:derived (reachable ?a ?b - place) (road ?a ?b))
  (:action drive
    :parameters (?t - truck ?a ?b - place)
    :precondition (and (at ?t ?a) (or (road ?a ?b) (road ?b ?a)) (>= (fuel ?t) 1))
    :effect (and (not (at ?t ?a)) (at ?t ?b) (decrease (fuel ?t) 1)
                 (forall (?u - truck) (when (at ?u ?b) (busy ?u)))))
  (:durative-action haul
    :parameters (?t - truck)
    :duration (= ?duration 5)
    :condition (at start (busy ?t))
    :effect (at end (not (busy ?t)))))
