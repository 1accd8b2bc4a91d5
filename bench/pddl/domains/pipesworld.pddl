; A pipesworld-like domain (after IPC 2004's Pipesworld, written for catplan's benchmarks): areas
; joined by pipes that are always full. Pushing a batch into a pipe from one end pushes the batch
; at the other end out into the far area, and only batches whose products may touch can be next
; to each other in a pipe; tanks hold at most one batch per slot.
(define (domain pipesworld)
  (:requirements :strips :typing)
  (:types area pipe batch product slot)
  (:predicates (connect ?from - area ?to - area ?p - pipe)
               (in-pipe ?b - batch ?p - pipe)
               (on ?b - batch ?a - area)
               (is-product ?b - batch ?pr - product)
               (may-interface ?x - product ?y - product)
               (tank-slot ?s - slot ?a - area)
               (occupied ?s - slot)
               (stored ?b - batch ?s - slot))
  (:action push
    :parameters (?p - pipe ?from - area ?to - area ?in - batch ?out - batch ?pin - product
                 ?pout - product ?sin - slot ?sout - slot)
    :precondition (and (connect ?from ?to ?p) (on ?in ?from) (in-pipe ?out ?p)
                       (is-product ?in ?pin) (is-product ?out ?pout) (may-interface ?pin ?pout)
                       (stored ?in ?sin) (tank-slot ?sin ?from) (tank-slot ?sout ?to)
                       (not (occupied ?sout)))
    :effect (and (in-pipe ?in ?p) (not (in-pipe ?out ?p)) (not (on ?in ?from)) (on ?out ?to)
                 (not (stored ?in ?sin)) (not (occupied ?sin)) (stored ?out ?sout)
                 (occupied ?sout)))
  (:action pop
    :parameters (?p - pipe ?from - area ?to - area ?in - batch ?out - batch ?pin - product
                 ?pout - product ?sin - slot ?sout - slot)
    :precondition (and (connect ?from ?to ?p) (on ?in ?to) (in-pipe ?out ?p)
                       (is-product ?in ?pin) (is-product ?out ?pout) (may-interface ?pin ?pout)
                       (stored ?in ?sin) (tank-slot ?sin ?to) (tank-slot ?sout ?from)
                       (not (occupied ?sout)))
    :effect (and (in-pipe ?in ?p) (not (in-pipe ?out ?p)) (not (on ?in ?to)) (on ?out ?from)
                 (not (stored ?in ?sin)) (not (occupied ?sin)) (stored ?out ?sout)
                 (occupied ?sout))))
