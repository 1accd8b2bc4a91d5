; Reverse a tower of three blocks with the gripper.
(define (problem tower3)
  (:domain blocks4)
  (:objects a b c - block)
  (:init (on a b) (on b c) (on-table c) (clear a) (hand-empty))
  (:goal (and (on c b) (on b a))))
