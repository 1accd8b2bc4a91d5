; From a to d: the road a-d is 20 long, a-b-c-d 3 + 4 + 5; the road a-e has no length in the
; table, so e (1 from d) cannot be reached that way.
(define (problem roads-p01)
  (:domain roads)
  (:objects a b c d e - city t1 - truck)
  (:init (at t1 a)
         (road a d) (road a b) (road b c) (road c d) (road a e) (road e d)
         (= (road-length a d) 20) (= (road-length a b) 3) (= (road-length b c) 4)
         (= (road-length c d) 5) (= (road-length e d) 1)
         (= (total-cost) 0))
  (:goal (at t1 d))
  (:metric minimize (total-cost)))
