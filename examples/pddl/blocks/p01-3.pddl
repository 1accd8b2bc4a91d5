; Reverse a tower of three blocks, moving one block at a time.
(define (problem tower3)
  (:domain blocks3)
  (:objects a b c - block)
  (:init (on a b) (on b c) (on-table c) (clear a))
  (:goal (and (on c b) (on b a))))
