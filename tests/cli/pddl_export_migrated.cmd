pddl export tests/pddl/lights.cp --problem LightsProblem --map LightsToRooms
