(define (problem rooms-p01) (:domain rooms)
  (:objects hall kitchen study - room)
  (:init (lit hall) (near hall kitchen) (near kitchen study))
  (:goal (lit study)))
