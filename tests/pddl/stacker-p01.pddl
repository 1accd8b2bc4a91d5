; The robot holds a block and must end at s2 with empty hands (s0 is the store).
(define (problem stacker-p01)
  (:domain stacker)
  (:objects s0 s1 s2 - spot t0 t1 - tier)
  (:init (robot-at s1) (holding) (store s0)
         (level s0 t0) (level s1 t0) (level s2 t0) (next t0 t1)
         (adjacent s0 s1) (adjacent s1 s0) (adjacent s1 s2) (adjacent s2 s1))
  (:goal (and (robot-at s2) (level s1 t0) (level s2 t0) (not (holding)))))
