; Reverse a tower of three blocks, one of them named with a non-ASCII letter (the transfer's
; step list pads such a line as it pads an ASCII one).
(define (problem blocks3-utf8-names)
  (:domain blocks3)
  (:objects a bé c - block)
  (:init (on a bé) (on bé c) (on-table c) (clear a))
  (:goal (and (on c bé) (on bé a))))
