; An object declared twice, and one that reuses the domain's constant.
(define (problem two-balls)
  (:domain rooms)
  (:objects ball1 ball1 - ball kitchen hall - room)
  (:init (at ball1 hall) (robot-in hall))
  (:goal (at ball1 kitchen)))
