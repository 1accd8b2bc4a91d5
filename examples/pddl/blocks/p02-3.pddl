; Two towers of three blocks, each reversed one block at a time: the same moves twice, on other
; blocks, so the second tower's repairs take the first tower's plans, renamed.
(define (problem towers6)
  (:domain blocks3)
  (:objects a b c d e f - block)
  (:init (on a b) (on b c) (on-table c) (clear a)
         (on d e) (on e f) (on-table f) (clear d))
  (:goal (and (on c b) (on b a) (on f e) (on e d))))
