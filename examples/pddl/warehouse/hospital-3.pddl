; The warehouse problem as the hospital's own: the same wards, courier and samples.
(define (problem hospital-3)
  (:domain hospital)
  (:objects dock aisle shelves - ward
            r1 - courier
            vase box - sample)
  (:init (courier-in r1 dock)
         (sample-in vase dock) (sample-in box dock)
         (adjacent dock aisle) (adjacent aisle dock)
         (adjacent aisle shelves) (adjacent shelves aisle)
         (hands-free r1)
         (biohazard vase))
  (:goal (and (sample-in vase shelves) (sample-in box shelves))))
