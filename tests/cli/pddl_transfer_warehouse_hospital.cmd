transfer examples/pddl/warehouse/hospital_to_warehouse.cp --map HospitalToWarehouse --problem examples/pddl/warehouse/warehouse-3.pddl --plan examples/pddl/warehouse/warehouse-3.plan --no-timing
