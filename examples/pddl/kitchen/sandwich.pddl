; Coloured blocks to be stacked purple on yellow, red, green, purple: through the map to the
; kitchen (blocks_to_kitchen.cp), a sandwich on a plate.
(define (problem sandwich) (:domain colorblocks)
  (:objects p1 p2 r1 g1 y1 - block)
  (:init (hand-empty)
         (on-table y1) (on p1 y1) (clear p1)
         (on-table g1) (on r1 g1) (on p2 r1) (clear p2)
         (purple p1) (purple p2) (red r1) (green g1) (yellow y1))
  (:goal (and (on p1 y1) (on r1 p1) (on g1 r1) (on p2 g1))))
