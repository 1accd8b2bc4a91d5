; A mystery-like domain (after IPC 1998's Mystery, written for catplan's benchmarks): vehicles
; carry cargo between locations; moving uses up one fuel unit of the location left, loading uses
; one unit of the vehicle's space and unloading gives it back. Fuel and space levels are objects
; ordered by neighbour facts.
(define (domain mystery)
  (:requirements :strips :typing)
  (:types location vehicle cargo fuel space)
  (:predicates (at ?v - vehicle ?l - location)
               (cargo-at ?c - cargo ?l - location)
               (in ?c - cargo ?v - vehicle)
               (conn ?l1 - location ?l2 - location)
               (has-fuel ?l - location ?f - fuel)
               (fuel-neighbor ?f1 - fuel ?f2 - fuel)
               (has-space ?v - vehicle ?s - space)
               (space-neighbor ?s1 - space ?s2 - space))
  (:action move
    :parameters (?v - vehicle ?l1 - location ?l2 - location ?f1 - fuel ?f2 - fuel)
    :precondition (and (at ?v ?l1) (conn ?l1 ?l2) (has-fuel ?l1 ?f1) (fuel-neighbor ?f2 ?f1))
    :effect (and (not (at ?v ?l1)) (at ?v ?l2) (not (has-fuel ?l1 ?f1)) (has-fuel ?l1 ?f2)))
  (:action load
    :parameters (?c - cargo ?v - vehicle ?l - location ?s1 - space ?s2 - space)
    :precondition (and (at ?v ?l) (cargo-at ?c ?l) (has-space ?v ?s1) (space-neighbor ?s2 ?s1))
    :effect (and (not (cargo-at ?c ?l)) (in ?c ?v) (not (has-space ?v ?s1)) (has-space ?v ?s2)))
  (:action unload
    :parameters (?c - cargo ?v - vehicle ?l - location ?s1 - space ?s2 - space)
    :precondition (and (at ?v ?l) (in ?c ?v) (has-space ?v ?s1) (space-neighbor ?s1 ?s2))
    :effect (and (cargo-at ?c ?l) (not (in ?c ?v)) (not (has-space ?v ?s1)) (has-space ?v ?s2))))
