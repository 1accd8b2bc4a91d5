; Two riders, three levels; the fast lift serves every level, the slow one only 0 and 1.
(define (problem lift-p01)
  (:domain lift)
  (:objects f0 f1 f2 - level
            slow0 - slow-lift
            fast0 - fast-lift
            ann bob - rider)
  (:init (up f0 f1) (up f0 f2) (up f1 f2)
         (lift-at slow0 f0) (lift-at fast0 f2)
         (serves slow0 f0) (serves slow0 f1)
         (serves fast0 f0) (serves fast0 f1) (serves fast0 f2)
         (rider-at ann f0) (rider-at bob f2)
         (= (travel-slow f0 f1) 6)
         (= (travel-fast f0 f1) 11) (= (travel-fast f0 f2) 13) (= (travel-fast f1 f2) 11)
         (= (total-cost) 0))
  (:goal (and (rider-at ann f1) (rider-at bob f0)))
  (:metric minimize (total-cost)))
