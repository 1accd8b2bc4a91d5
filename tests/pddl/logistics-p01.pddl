; One package from a post office in city1 to one in city2.
(define (problem logistics-p01)
  (:domain logistics)
  (:objects city1 city2 - city
            office1 office2 - location
            airport1 airport2 - airport
            truck1 truck2 - truck
            plane1 - airplane
            pkg1 - package)
  (:init (in-city office1 city1) (in-city airport1 city1)
         (in-city office2 city2) (in-city airport2 city2)
         (at truck1 office1) (at truck2 airport2) (at plane1 airport1)
         (at pkg1 office1))
  (:goal (at pkg1 office2)))
