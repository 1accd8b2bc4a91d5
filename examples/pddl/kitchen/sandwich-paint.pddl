; The sandwich of sandwich.pddl with one purple block short: a red block is painted purple. Through
; the map (blocks_to_kitchen.cp) the painted block would have to turn from a tomato into bread,
; which no kitchen action does.
(define (problem sandwich-paint) (:domain colorblocks)
  (:objects p1 r1 r2 g1 y1 - block)
  (:init (hand-empty)
         (on-table y1) (on p1 y1) (clear p1)
         (on-table g1) (on r1 g1) (on r2 r1) (clear r2)
         (purple p1) (red r1) (red r2) (green g1) (yellow y1))
  (:goal (and (on p1 y1) (on r1 p1) (on g1 r1) (on r2 g1) (purple r2))))
