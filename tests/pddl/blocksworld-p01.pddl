; Five blocks: e on d on c, a and b on the table; goal the tower a b c d e (a on top).
(define (problem blocksworld-p01)
  (:domain blocksworld)
  (:objects a b c d e - block)
  (:init (handempty)
         (ontable a) (ontable b) (ontable c)
         (on d c) (on e d)
         (clear a) (clear b) (clear e))
  (:goal (and (on d e) (on c d) (on b c) (on a b))))
