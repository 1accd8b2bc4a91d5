# A delta map from the hospital to the warehouse: every hospital type and predicate is a
# warehouse one (a courier is a robot, a ward a location), so a warehouse plan is a hospital
# plan. Each migrated action is a hospital action up to the names and the order of its
# parameters (move is walk, pick is collect); the actions section names drop => deliver, which
# is checked the same way.
@import "warehouse.pddl"
@import "hospital.pddl"

@migration HospitalToWarehouse(hospital, warehouse) begin
  object => object
  ward => location
  courier => robot
  sample => crate
  courier-in => robot-at
  sample-in => crate-at
  adjacent => connected
  holds => carrying
  hands-free => free
  biohazard => fragile
  actions => begin
    drop => deliver
  end
end
