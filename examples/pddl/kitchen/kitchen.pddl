; A kitchen counter worked with one hand: items are taken from the counter or from the item they
; rest on, and set down on the counter or on another item. Bread, tomatoes, lettuce and plates
; are items.
(define (domain kitchen)
  (:requirements :strips :typing)
  (:types item - object
          bread tomato lettuce plate - item)
  (:predicates (on ?x - item ?y - item)
               (on-counter ?x - item)
               (free ?x - item)
               (hand-free)
               (holds ?x - item))
  (:action take
    :parameters (?x - item)
    :precondition (and (free ?x) (on-counter ?x) (hand-free))
    :effect (and (holds ?x) (not (on-counter ?x)) (not (free ?x)) (not (hand-free))))
  (:action set-down
    :parameters (?x - item)
    :precondition (holds ?x)
    :effect (and (on-counter ?x) (free ?x) (hand-free) (not (holds ?x))))
  (:action place
    :parameters (?x - item ?y - item)
    :precondition (and (holds ?x) (free ?y))
    :effect (and (on ?x ?y) (free ?x) (hand-free) (not (holds ?x)) (not (free ?y))))
  (:action take-from
    :parameters (?x - item ?y - item)
    :precondition (and (on ?x ?y) (free ?x) (hand-free))
    :effect (and (holds ?x) (free ?y) (not (on ?x ?y)) (not (free ?x)) (not (hand-free)))))
