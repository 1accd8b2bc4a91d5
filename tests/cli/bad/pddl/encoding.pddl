; A byte that is not UTF-8 (0xFF) in a name.
(define (domain badÿ)
  (:predicates (p)))
