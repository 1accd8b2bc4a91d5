; Two crates from the dock to the shelves, one of them fragile.
(define (problem warehouse-3)
  (:domain warehouse)
  (:objects dock aisle shelves - location
            r1 - robot
            vase box - crate)
  (:init (robot-at r1 dock)
         (crate-at vase dock) (crate-at box dock)
         (connected dock aisle) (connected aisle dock)
         (connected aisle shelves) (connected shelves aisle)
         (free r1)
         (fragile vase))
  (:goal (and (crate-at vase shelves) (crate-at box shelves))))
