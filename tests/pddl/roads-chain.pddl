; A chain of eight cities, each road 2 long but the fourth, 60 long. Carried along ToCharters
; (roads_to_transit.cp), a drive of 2 is repaired by a departure and an arrival, and the drive
; of 60 by a charter, which costs 50: the repairs of the 2-long roads are one search, reused,
; and the 60-long one, the same problem but for its values, is searched on its own.
(define (problem roads-chain)
  (:domain roads)
  (:objects c0 c1 c2 c3 c4 c5 c6 c7 - city t1 - truck)
  (:init (at t1 c0)
         (road c0 c1) (road c1 c2) (road c2 c3) (road c3 c4) (road c4 c5) (road c5 c6) (road c6 c7)
         (= (road-length c0 c1) 2)
         (= (road-length c1 c2) 2)
         (= (road-length c2 c3) 2)
         (= (road-length c3 c4) 60)
         (= (road-length c4 c5) 2)
         (= (road-length c5 c6) 2)
         (= (road-length c6 c7) 2)
         (= (total-cost) 0))
  (:goal (at t1 c7))
  (:metric minimize (total-cost)))
