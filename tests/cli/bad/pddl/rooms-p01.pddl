; Two balls in the hall; the goal: both in the kitchen.
(define (problem rooms-p01)
  (:domain rooms)
  (:objects ball1 ball2 - ball kitchen - room)
  (:init (at ball1 hall) (at ball2 hall) (robot-in hall))
  (:goal (and (at ball1 kitchen) (at ball2 kitchen))))
